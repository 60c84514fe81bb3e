// Scene and mesh files through the real executable: every shipped scene opens, bad files are
// refused with one line and exit code 2, and OBJ sequences come out for other tools.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../shared_constants.h"
#include "app/cli/scene_catalog.h"
#include "io/load_scene.h"
#include "io/png_image.h"
#include "run_wobble.h"

namespace {

using wobble::testing::run_wobble;
using wobble::testing::TemporaryFolder;

using wobble::testing::assets;

TEST(SceneFiles, EveryShippedSceneAndMeshOpensHeadless) {
  std::vector<std::string> sources;
  for (const auto& entry : std::filesystem::directory_iterator(assets)) {
    if (entry.path().extension() == ".json") sources.push_back(entry.path().string());
  }
  EXPECT_GE(sources.size(), 5u);
  sources.push_back(assets + "/course/banner.json");  // course format, with a texture
  sources.push_back(assets + "/course/rope.json");    // course format, springs only
  sources.push_back(assets + "/meshes/blob.obj");     // a bare OBJ
  sources.push_back(assets + "/meshes/jelly_cube.mesh");
  sources.push_back(assets + "/meshes/column.node");
  TemporaryFolder folder;
  for (const std::string& source : sources) {
    const std::string shot = folder.file(std::filesystem::path(source).stem().string() + ".png");
    const auto run = run_wobble("'" + source +
                                    "' --headless --frames 2 --width 96 --height 72 "
                                    "--screenshot '" +
                                    shot + "'",
                                "DISPLAY=");
    EXPECT_EQ(run.exit_code, 0) << source << ": " << run.err;
    if (run.exit_code == 0) {
      EXPECT_EQ(wobble::read_png(shot).width, 96) << source;
    }
  }
}

TEST(SceneFiles, ABareObjSaysWhichVerticesItPinned) {
  const auto run = run_wobble("'" + assets + "/meshes/blob.obj' --headless --frames 1");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("wobble: note: no pins given: pinned the"), std::string::npos) << run.err;
}

TEST(SceneFiles, BadFilesAreRefusedWithOneLineAndNothingWritten) {
  TemporaryFolder folder;
  std::ofstream(folder.file("bad.json"))
      << "{\"mesh\": {\"generator\": \"cloth\"},\n \"pins\": [-1]}";
  std::ofstream(folder.file("bad.obj")) << "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
  std::ofstream(folder.file("empty.json")) << "";
  for (const std::string name : {"bad.json", "bad.obj", "empty.json", "missing.json"}) {
    const auto run =
        run_wobble("'" + folder.file(name) + "' --headless --frames 5 --export-obj '" +
                   folder.file("out.obj") + "' --screenshot '" + folder.file("out.png") + "'");
    EXPECT_EQ(run.exit_code, 2) << name << ": " << run.err;
    EXPECT_NE(run.err.find(name), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  }
  EXPECT_FALSE(std::filesystem::exists(folder.file("out.obj")));
  EXPECT_FALSE(std::filesystem::exists(folder.file("out.png")));
}

TEST(SceneFiles, ObjSequenceWritesEveryFrameAndLoadsBack) {
  TemporaryFolder folder;
  const std::string sequence = folder.file("objs");
  const auto run = run_wobble("jelly --headless --frames 4 --export-obj-sequence '" + sequence +
                              "' --export-obj '" + folder.file("last.obj") + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (int frame = 1; frame <= 4; ++frame) {
    const std::string file = sequence + "/frame_0000" + std::to_string(frame) + ".obj";
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
  }
  EXPECT_FALSE(std::filesystem::exists(sequence + "/frame_00005.obj"));
  // The last frame of the sequence is the final export, and it opens as a scene again.
  EXPECT_EQ(wobble::testing::read_text(sequence + "/frame_00004.obj"),
            wobble::testing::read_text(folder.file("last.obj")));
  const wobble::Scene again = wobble::load_scene(sequence + "/frame_00004.obj");
  EXPECT_EQ(again.network.V.rows(), 729);
}

TEST(SceneFiles, FillTurnsAClosedSurfaceIntoAJelly) {
  const auto run = run_wobble("'" + assets +
                              "/meshes/blob.obj' --fill --headless --frames 1 "
                              "--stats");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("lowest"), std::string::npos) << run.err;  // a jelly stands on its base
  const auto refused = run_wobble("cloth --fill --headless --frames 1");
  EXPECT_EQ(refused.exit_code, 2);
}

}  // namespace

// The picker and --list-scenes offer the scene files of assets/ and its subfolders: the course's
// scenes in assets/course/ too.
TEST(SceneCatalog, ListsTheSubfoldersOfAssets) {
  const std::vector<std::string> catalog = wobble::scene_catalog();
  const auto listed = [&](const std::string& ending) {
    for (const std::string& source : catalog) {
      if (source.size() >= ending.size() &&
          source.compare(source.size() - ending.size(), ending.size(), ending) == 0) {
        return true;
      }
    }
    return false;
  };
  EXPECT_TRUE(listed("/assets/drape.json"));
  EXPECT_TRUE(listed("/assets/course/banner.json"));
  EXPECT_TRUE(listed("/assets/course/rope.json"));
  const wobble::testing::Result result = wobble::testing::run_wobble("--list-scenes");
  EXPECT_NE(result.out.find("course/rope.json"), std::string::npos) << result.out;
}

// The picker says what each scene shows and lists the course's scenes apart: every scene of the
// catalogue has a description (read from its file, or made from a course scene's mesh, k and
// pins), and exactly the files of assets/course/ are the course's.
TEST(SceneCatalog, EachSceneSaysWhatItShowsAndTheCoursesAreApart) {
  int course = 0;
  for (const std::string& source : wobble::scene_catalog()) {
    const std::string description = wobble::scene_description(source);
    EXPECT_FALSE(description.empty()) << source;
    const bool in_course = source.find("/course/") != std::string::npos;
    EXPECT_EQ(wobble::is_course_scene_source(source), in_course) << source;
    course += in_course;
    if (wobble::scene_label(source) == "banner") {
      EXPECT_EQ(description, "the course's scene: banner.obj, k = 2000, 2 pins");
    }
    if (wobble::scene_label(source) == "curtain") {
      EXPECT_EQ(description,
                "the paper's curtain: 81 x 81 vertices hanging from a rail, pushed once");
    }
  }
  EXPECT_EQ(course, 2) << "banner and rope";
  EXPECT_EQ(wobble::scene_description("cloth"), "40x40 cloth hanging from its two top corners");
  EXPECT_EQ(wobble::scene_description("/no/such/file.json"), "") << "said when it is chosen";
}
