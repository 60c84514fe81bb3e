#include "io/read_json_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "sim/input_error.h"
#include "temporary_folder.h"

namespace {

using wobble::testing::TemporaryFolder;

// The InputError message that reading `text` as FOLDER/scene.json gives.
std::string error_of(const TemporaryFolder& folder, const std::string& text) {
  std::ofstream(folder.file("scene.json")) << text;
  try {
    wobble::read_json_file(folder.file("scene.json"));
  } catch (const wobble::InputError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(ReadJsonFile, ParsesAnObject) {
  TemporaryFolder folder;
  std::ofstream(folder.file("scene.json")) << R"({"k": 2000, "b": [1, 11], "m": 1e300})";
  const nlohmann::json object = wobble::read_json_file(folder.file("scene.json"));
  EXPECT_EQ(object.at("k"), 2000);
  EXPECT_EQ(object.at("b"), nlohmann::json::array({1, 11}));
  EXPECT_EQ(object.at("m").get<double>(), 1e300);
}

TEST(ReadJsonFile, SyntaxErrorNamesItsLine) {
  TemporaryFolder folder;
  EXPECT_EQ(error_of(folder, "{\n  \"k\": 1,\n  oops\n}"),
            folder.file("scene.json") +
                ": line 3: malformed JSON: syntax error while parsing object key - invalid "
                "literal; last read: '1,<U+000A>  o'; expected string literal");
}

// Found by fuzz_course_scene: nlohmann reports a number too large for a double with
// out_of_range, not parse_error, and it escaped the loaders as a crash.
TEST(ReadJsonFile, NumberTooLargeForADoubleNamesItsLine) {
  TemporaryFolder folder;
  EXPECT_EQ(
      error_of(folder, "{\n  \"k\": 1e400\n}"),
      folder.file("scene.json") + ": line 2: malformed JSON: number overflow parsing '1e400'");
  EXPECT_EQ(
      error_of(folder, "-1e3086locale5bje~000"),
      folder.file("scene.json") + ": line 1: malformed JSON: number overflow parsing '-1e3086'");
}

TEST(ReadJsonFile, MissingFileIsNamed) {
  TemporaryFolder folder;
  try {
    wobble::read_json_file(folder.file("none.json"));
    FAIL() << "no error";
  } catch (const wobble::InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              folder.file("none.json") + ": no such file, expected a scene (JSON)");
  }
}

}  // namespace
