// SaveAndRecord on its own, in a folder of its own: F12 writes the frame drawn once, under the
// next free number; F9 records each new state into a folder of its own and says so when it
// stops; Ctrl+S and F11 write a scene and an OBJ that read back.
#include "app/viewer/save_and_record.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/viewer/instruments.h"
#include "io/load_scene.h"
#include "io/png_image.h"
#include "sim/instruments/frame_energy.h"
#include "sim/shapes/builtin_scenes.h"
#include "sim/simulation.h"

namespace {

namespace fs = std::filesystem;

// The test runs in a fresh folder, and goes back where it was after.
class InFreshFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    previous_ = fs::current_path();
    folder_ = fs::temp_directory_path() /
              ("wobble_save_and_record_" + std::to_string(getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
    fs::current_path(folder_);
  }
  void TearDown() override {
    fs::current_path(previous_);
    fs::remove_all(folder_);
  }
  fs::path folder_, previous_;
};

wobble::RgbaImage grey_frame() {
  wobble::RgbaImage image;
  image.width = 4;
  image.height = 3;
  image.pixels.assign(4 * 3 * 4, 128);
  return image;
}

using SaveAndRecordTest = InFreshFolder;

TEST_F(SaveAndRecordTest, F12WritesTheNextFrameDrawnOnceUnderTheNextNumber) {
  wobble::SaveAndRecord saves;
  int reads = 0;
  const auto read = [&] {
    ++reads;
    return grey_frame();
  };
  EXPECT_TRUE(saves.write_frame("cloth", 1, true, read).empty()) << "nothing asked";
  EXPECT_TRUE(saves.command(wobble::ViewerCommand::screenshot));
  EXPECT_FALSE(saves.command(wobble::ViewerCommand::reset)) << "not its command";
  // A minimized window draws nothing: the request is dropped, nothing read.
  EXPECT_TRUE(saves.write_frame("cloth", 1, false, read).empty());
  EXPECT_EQ(reads, 0);
  saves.command(wobble::ViewerCommand::screenshot);
  EXPECT_EQ(saves.write_frame("cloth", 2, true, read),
            std::vector<std::string>{"saved ./wobble-cloth-0001.png"});
  saves.command(wobble::ViewerCommand::screenshot);
  EXPECT_EQ(saves.write_frame("cloth", 3, true, read),
            std::vector<std::string>{"saved ./wobble-cloth-0002.png"});
  EXPECT_TRUE(saves.write_frame("cloth", 4, true, read).empty()) << "once per press";
  EXPECT_EQ(reads, 2);
  EXPECT_TRUE(fs::exists("wobble-cloth-0001.png"));
  EXPECT_TRUE(fs::exists("wobble-cloth-0002.png"));
}

TEST_F(SaveAndRecordTest, F9RecordsEachNewStateIntoAFolderOfItsOwn) {
  wobble::SaveAndRecord saves;
  std::ostringstream progress;
  saves.record_into(".", progress);
  EXPECT_TRUE(saves.command(wobble::ViewerCommand::toggle_record));
  EXPECT_TRUE(saves.recording());
  for (long step : {1, 1, 2, 3})  // step 1 drawn twice: one picture
    saves.write_frame("cloth", step, true, grey_frame);
  saves.command(wobble::ViewerCommand::toggle_record);
  const std::vector<std::string> told = saves.write_frame("cloth", 4, true, grey_frame);
  ASSERT_EQ(told.size(), 1u);
  EXPECT_NE(told[0].find("3 frames"), std::string::npos) << told[0];
  int folders = 0, frames = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(".")) {
    if (!entry.is_directory()) continue;
    ++folders;
    for (const fs::directory_entry& frame : fs::directory_iterator(entry.path()))
      frames += frame.path().extension() == ".png";
  }
  EXPECT_EQ(folders, 1);
  EXPECT_EQ(frames, 3);
}

// What a recorded frame shows: the scene as drawn before the panel went over it (the default,
// for slides), or, with the combo on "whole window", the frame the window shows.
TEST_F(SaveAndRecordTest, F9RecordsTheSceneAloneUnlessTheWholeWindowIsAsked) {
  const auto coloured = [](unsigned char value) {
    wobble::RgbaImage image = grey_frame();
    image.pixels.assign(image.pixels.size(), value);
    return image;
  };
  for (const bool whole : {false, true}) {
    wobble::SaveAndRecord saves;
    std::ostringstream progress;
    saves.record_into(".", progress);
    saves.set_record_whole_window(whole);
    saves.command(wobble::ViewerCommand::toggle_record);
    int scene_reads = 0;
    for (long step : {1, 2}) {
      saves.scene_drawn([&] {
        ++scene_reads;
        return coloured(60);  // the scene alone
      });
      saves.write_frame("cloth", step, true, [&] { return coloured(200); });  // with the panel
    }
    saves.command(wobble::ViewerCommand::toggle_record);
    const std::vector<std::string> told =
        saves.write_frame("cloth", 3, true, [&] { return coloured(200); });
    ASSERT_EQ(told.size(), 1u);
    const std::string folder = whole ? "wobble-cloth-frames-0002" : "wobble-cloth-frames-0001";
    EXPECT_NE(told[0].find(folder), std::string::npos) << told[0];
    EXPECT_EQ(scene_reads, whole ? 0 : 2) << "the scene is read only when it is recorded";
    for (const char* frame : {"frame_00001.png", "frame_00002.png"}) {
      const wobble::RgbaImage written = wobble::read_png(folder + "/" + frame);
      EXPECT_EQ(written.pixels[0], whole ? 200 : 60) << folder << "/" << frame;
    }
  }
}

// With the record combo on a video, F9 writes one file, wobble-SCENE-NNNN.webm, beside the
// other saves: each new state a frame (VideoFile's own test decodes them), and the notice
// names the file.
TEST_F(SaveAndRecordTest, F9RecordsAVideoFileWhenTheComboSaysSo) {
  wobble::SaveAndRecord saves;
  std::ostringstream progress;
  saves.record_into(".", progress);
  saves.set_record_format(wobble::VideoFormat::webm);
  saves.command(wobble::ViewerCommand::toggle_record);
  const auto frame = [] {
    wobble::RgbaImage image;
    image.width = 33;  // odd: cropped to 32
    image.height = 24;
    image.pixels.assign(33 * 24 * 4, 200);
    return image;
  };
  for (long step : {1, 1, 2, 3})  // step 1 drawn twice: one frame
    saves.write_frame("cloth", step, true, frame, wobble::FrameTime{step / 60.0, 1 / 60.0});
  saves.command(wobble::ViewerCommand::toggle_record);
  const std::vector<std::string> told = saves.write_frame("cloth", 4, true, frame);
  ASSERT_EQ(told.size(), 1u);
  EXPECT_EQ(told[0], "recorded 3 frames as ./wobble-cloth-0001.webm");
  std::ifstream file("wobble-cloth-0001.webm", std::ios::binary);
  char magic[4] = {};
  file.read(magic, 4);
  EXPECT_EQ(std::string(magic, 4), std::string("\x1a\x45\xdf\xa3", 4)) << "a Matroska file";
  EXPECT_FALSE(fs::exists("wobble-cloth-frames-0001"));
}

// Each file written is told by its path (the page offers each as a download): the screenshot,
// the OBJ, and a saved scene's mesh and scene file.
TEST_F(SaveAndRecordTest, EachFileWrittenIsToldByItsPath) {
  wobble::Scene scene = wobble::make_builtin_scene("cloth");
  wobble::Simulation simulation(scene.network, scene.pins, scene.params);
  wobble::SaveAndRecord saves;
  std::vector<std::string> written;
  saves.set_written([&](const std::string& path) { written.push_back(path); });
  saves.command(wobble::ViewerCommand::screenshot);
  saves.write_frame("cloth", 1, true, grey_frame);
  saves.export_obj(scene, simulation);
  const wobble::SavedScene saved = saves.save_scene(scene, simulation, wobble::OrbitCamera());
  EXPECT_EQ(written, (std::vector<std::string>{"./wobble-cloth-0001.png", "./wobble-cloth-0001.obj",
                                               "./wobble-cloth-scene-0001.obj", saved.path}));
  for (const std::string& path : written)
    EXPECT_TRUE(fs::exists(path)) << path;
}

// The instruments' CSV button: what the plots show, as files a spreadsheet reads. The
// convergence plot's step has a row per iterate with the trace's own numbers, read back exactly;
// the energy plot's samples a row each; both told by path (the page downloads them).
TEST_F(SaveAndRecordTest, TheCsvButtonWritesWhatThePlotsShow) {
  wobble::Scene scene = wobble::make_builtin_scene("cloth");
  wobble::Simulation simulation(scene.network, scene.pins, scene.params);
  simulation.set_convergence_recording(true);
  wobble::Instruments instruments;
  std::vector<std::pair<double, wobble::FrameEnergy>> samples;
  for (int i = 0; i < 3; ++i) {
    simulation.step();
    samples.emplace_back(simulation.time(), wobble::frame_energy(simulation));
  }
  wobble::ConvergenceTrace trace = simulation.last_convergence();
  const wobble::ConvergenceTrace expected = trace;
  ASSERT_GT(expected.iterations(), 0);
  wobble::SaveAndRecord saves;
  EXPECT_EQ(saves.save_plots("cloth", instruments.convergence_csv(), ""), "")
      << "nothing plotted yet: nothing written";
  instruments.take(trace, 3, samples);
  std::vector<std::string> written;
  saves.set_written([&](const std::string& path) { written.push_back(path); });
  const std::string told =
      saves.save_plots("cloth", instruments.convergence_csv(), instruments.energy_csv());
  EXPECT_EQ(told,
            "saved the plots as ./wobble-cloth-convergence-0001.csv and "
            "./wobble-cloth-energy-0001.csv");
  ASSERT_EQ(written.size(), 2u);
  std::ifstream convergence(written[0]);
  std::string line;
  std::getline(convergence, line);
  EXPECT_EQ(line, "frame,iteration,energy,gradient_norm,solver");
  int rows = 0;
  while (std::getline(convergence, line)) {
    std::istringstream fields(line);
    std::string step, iteration, energy, gradient, solver;
    std::getline(fields, step, ',');
    std::getline(fields, iteration, ',');
    std::getline(fields, energy, ',');
    std::getline(fields, gradient, ',');
    std::getline(fields, solver, ',');
    EXPECT_EQ(step, "3");
    EXPECT_EQ(std::stoi(iteration), rows);
    EXPECT_EQ(std::stod(energy), expected.energy[rows]) << line;
    EXPECT_EQ(std::stod(gradient), expected.gradient_norm[rows]) << line;
    EXPECT_EQ(solver, "local-global");
    ++rows;
  }
  EXPECT_EQ(rows, expected.iterations() + 1);
  std::ifstream energy(written[1]);
  std::getline(energy, line);
  EXPECT_EQ(line, "time,kinetic,spring,gravity,total");
  int samples_read = 0;
  while (std::getline(energy, line)) {
    EXPECT_EQ(std::stod(line.substr(0, line.find(','))), samples[samples_read].first);
    ++samples_read;
  }
  EXPECT_EQ(samples_read, 3);
}

TEST_F(SaveAndRecordTest, CtrlSAndF11WriteASceneAndAnObjThatReadBack) {
  wobble::Scene scene = wobble::make_builtin_scene("cloth");
  wobble::Simulation simulation(scene.network, scene.pins, scene.params);
  for (int i = 0; i < 5; ++i)
    simulation.step();
  wobble::SaveAndRecord saves;
  const wobble::SavedScene saved = saves.save_scene(scene, simulation, wobble::OrbitCamera());
  ASSERT_FALSE(saved.path.empty()) << saved.message;
  const wobble::Scene back = wobble::load_scene(saved.path);
  EXPECT_EQ(back.network.V.rows(), scene.network.V.rows());
  EXPECT_EQ(back.pins, scene.pins);
  EXPECT_EQ(saves.export_obj(scene, simulation), "exported ./wobble-" + scene.name + "-0001.obj");
  EXPECT_TRUE(fs::exists("wobble-" + scene.name + "-0001.obj"));
}

}  // namespace
