// ViewerFiles, what the viewer opens and tells, on its own: of files dropped together the scene
// file opens, with the source it came from; a file that does not open is told, the page's own
// folder left out of what is said; and a line told reaches the notes and the screen.
#include "app/viewer/viewer_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../../io/temporary_folder.h"

namespace {

struct FilesFixture {
  explicit FilesFixture(bool page = false)
      : files(
            wobble::ViewerFiles::Hooks{[this](wobble::Scene scene, const std::string& source) {
                                         opened.push_back(scene.name + " from " + source);
                                       },
                                       [this](const std::string& what) { notes.push_back(what); }},
            page) {}
  std::vector<std::string> opened, notes;
  wobble::ViewerFiles files;
};

const std::string course = std::string(WOBBLE_ASSETS_DIR) + "/course";

TEST(ViewerFiles, OfFilesDroppedTogetherTheSceneFileOpens) {
  FilesFixture f;
  const std::string scene = course + "/banner.json", mesh = course + "/banner.obj";
  ASSERT_TRUE(f.files.open_files({scene, mesh}));
  ASSERT_EQ(f.opened.size(), 1u);
  EXPECT_NE(f.opened[0].find(" from " + scene), std::string::npos) << f.opened[0];
  EXPECT_FALSE(f.files.open_files({}));
}

TEST(ViewerFiles, AFileThatDoesNotOpenIsToldWithoutThePagesFolder) {
  wobble::testing::TemporaryFolder folder;
  const std::string dropped = folder.file("opened_1");
  std::filesystem::create_directories(dropped);
  // The course's banner without its mesh beside it.
  std::filesystem::copy_file(course + "/banner.json", dropped + "/banner.json");
  for (const bool page : {true, false}) {
    FilesFixture f(page);
    EXPECT_FALSE(f.files.open_files({dropped + "/banner.json"}));
    EXPECT_TRUE(f.opened.empty());
    ASSERT_EQ(f.notes.size(), 1u);
    EXPECT_EQ(f.notes[0].find(dropped) == std::string::npos, page) << f.notes[0];
    ASSERT_EQ(f.files.notices().shown(wobble::notice_clock()).size(), 1u);
  }
}

TEST(ViewerFiles, ALineToldIsANoteAndANotice) {
  FilesFixture f;
  f.files.tell("saved wobble-cloth.png");
  EXPECT_EQ(f.notes, std::vector<std::string>{"saved wobble-cloth.png"});
  EXPECT_EQ(f.files.notices().shown(wobble::notice_clock()),
            std::vector<std::string>{"saved wobble-cloth.png"});
  f.files.post("the wind blows");
  EXPECT_EQ(f.notes.size(), 1u) << "posted on screen only";
}

}  // namespace
