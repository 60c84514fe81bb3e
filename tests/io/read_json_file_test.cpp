#include "io/read_json_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "io/input_file_limits.h"
#include "sim/input_error.h"
#include "temporary_folder.h"

namespace {

using wobble::testing::TemporaryFolder;

// The InputError message that reading `text` as FOLDER/scene.json gives.
std::string read_error(const TemporaryFolder& folder, const std::string& text) {
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
  EXPECT_EQ(read_error(folder, "{\n  \"k\": 1,\n  oops\n}"),
            folder.file("scene.json") +
                ": line 3: malformed JSON: syntax error while parsing object key - invalid "
                "literal; last read: '1,<U+000A>  o'; expected string literal");
}

// Found by fuzz_course_scene: nlohmann reports a number too large for a double with
// out_of_range, not parse_error, and it escaped the loaders as a crash.
TEST(ReadJsonFile, NumberTooLargeForADoubleNamesItsLine) {
  TemporaryFolder folder;
  EXPECT_EQ(
      read_error(folder, "{\n  \"k\": 1e400\n}"),
      folder.file("scene.json") + ": line 2: malformed JSON: number overflow parsing '1e400'");
  EXPECT_EQ(
      read_error(folder, "-1e3086locale5bje~000"),
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

// nlohmann keeps the last of two equal keys without a word; a scene must not mean something
// else than it seems to. Refused while parsing, for every object of the file, with the line of
// the second key and, below the top, the object's path.
TEST(ReadJsonFile, KeyThatAppearsTwiceIsRefused) {
  TemporaryFolder folder;
  const std::string at = folder.file("scene.json") + ": ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"k": 1, "k": 2})", "line 1: key \"k\" appears twice in the same object"},
      {"{\n  \"mesh\": {\"generator\": \"cloth\"},\n  \"pins\": \"top\",\n"
       "  \"mesh\": {\"generator\": \"jelly\"}\n}",
       "line 4: key \"mesh\" appears twice in the same object"},
      {"{\"colliders\": [{\"type\": \"ground\"},\n {\"type\": \"sphere\",\n  \"type\": \"box\"}]}",
       "line 3: key \"type\" appears twice in the same object (colliders[1])"},
      {R"({"material": {"k": 1, "density": 2, "k": 3}})",
       "line 1: key \"k\" appears twice in the same object (material)"},
      {R"({"simulation": {"wind": {"velocity": [1, 0, 0], "velocity": [0, 0, 1]}}})",
       "line 1: key \"velocity\" appears twice in the same object (simulation.wind)"},
      {R"({"pins": [0, {"below": 1, "below": 2}]})",
       "line 1: key \"below\" appears twice in the same object (pins[1])"},
      // Keys are compared as parsed: an escape spells the same key.
      {R"({"k": 1, "\u006b": 2})", "line 1: key \"k\" appears twice in the same object"},
      // A key holding a line break is shown escaped, and the message stays one line.
      {"{\"a\\nb\": 1, \"a\\nb\": 2}", "line 1: key \"a\\nb\" appears twice in the same object"},
  };
  for (const auto& [text, expected] : cases) {
    EXPECT_EQ(read_error(folder, text), at + expected) << text;
  }
  // The same key in two different objects, or as a value, is fine.
  std::ofstream(folder.file("scene.json"), std::ios::trunc)
      << R"({"a": {"k": 1}, "b": {"k": 2}, "k": ["k", "k"], "c": [{"k": 1}, {"k": 2}]})";
  EXPECT_EQ(wobble::read_json_file(folder.file("scene.json")).at("b").at("k"), 2);
}

// What a scene's JSON may hold is bounded (io/input_file_limits.h) and checked before any of
// it is kept; the limits themselves parse.
TEST(ReadJsonFile, LimitsAreCheckedWhileParsing) {
  TemporaryFolder folder;
  const std::string at = folder.file("scene.json") + ": ";
  const auto list = [](long items, const std::string& item) {
    std::string text = "[";
    for (long i = 0; i < items; ++i)
      text += (i ? "," : "") + item;
    return text + "]";
  };
  const long items = wobble::max_json_list_items;
  std::ofstream(folder.file("scene.json")) << "{\"a\": " + list(items, "0") + "}";
  EXPECT_EQ(wobble::read_json_file(folder.file("scene.json")).at("a").size(),
            static_cast<std::size_t>(items));
  EXPECT_EQ(read_error(folder, "{\"a\": " + list(items / 2, "1") +
                                   ",\n\"b\": " + list(items / 2 + 1, "2") + "}"),
            at + "line 2: more than 1,000,000 items in all lists, above Wobble's limit for a "
                 "scene (JSON)");
  // Empty lists inside a list count as its items.
  EXPECT_NE(read_error(folder, list(items + 1, "[]")).find("more than 1,000,000 items"),
            std::string::npos);

  std::string keys = "{";
  for (long i = 0; i <= wobble::max_json_keys; ++i)
    keys += (i ? ",\n\"k" : "\"k") + std::to_string(i) + "\": 0";
  EXPECT_EQ(read_error(folder, keys + "}"),
            at + "line 10001: more than 10,000 keys in all objects, above Wobble's limit for a "
                 "scene (JSON)");

  const std::string deep_ok =
      std::string(wobble::max_json_depth, '[') + std::string(wobble::max_json_depth, ']');
  EXPECT_EQ(read_error(folder, deep_ok), "(no error)");
  EXPECT_EQ(read_error(folder, "[" + deep_ok + "]"),
            at + "line 1: lists and objects nested more than 64 deep, above Wobble's limit for a "
                 "scene (JSON)");

  const std::string longest(wobble::max_json_string_bytes, 'x');
  EXPECT_EQ(read_error(folder, "{\"name\": \"" + longest + "\"}"), "(no error)");
  EXPECT_EQ(read_error(folder, "{\"name\":\n\"" + longest + "x\"}"),
            at + "line 2: a string longer than 65,536 bytes, above Wobble's limit for a key or "
                 "string in a scene (JSON)");
  // Escapes count as written: a string of quotes and backslashes is still a string.
  EXPECT_EQ(read_error(folder, "{\"name\": \"\\\"\\\\\", \"k\": \"" + longest + "y\"}"),
            at + "line 1: a string longer than 65,536 bytes, above Wobble's limit for a key or "
                 "string in a scene (JSON)");
  EXPECT_NE(read_error(folder, "{\"" + longest + "z\": 1}").find("a string longer than"),
            std::string::npos);
}

TEST(ReadJsonFile, ByteOrderMarkIsSkippedAndLinesCountFromTheText) {
  TemporaryFolder folder;
  std::ofstream(folder.file("scene.json")) << "\xEF\xBB\xBF{\"k\": [1,\n 2]}";
  EXPECT_EQ(wobble::read_json_file(folder.file("scene.json")).at("k").size(), 2u);
  EXPECT_EQ(read_error(folder, "\xEF\xBB\xBF{\n\n\"k\": 1,\n\"k\": 2}"),
            folder.file("scene.json") + ": line 4: key \"k\" appears twice in the same object");
  EXPECT_EQ(read_error(folder, "\xEF\xBB\xBF"),
            folder.file("scene.json") + ": the file is empty, expected a JSON object");
  // A document spread over more than one 64 KiB block reads whole, lines counted across blocks.
  std::string text = "{\"a\": [";
  for (int i = 0; i < 40000; ++i)
    text += (i ? ",\n" : "") + std::to_string(i);
  std::ofstream(folder.file("scene.json"), std::ios::trunc) << text + "], \"b\": 1}";
  EXPECT_EQ(wobble::read_json_file(folder.file("scene.json")).at("a").at(39999), 39999);
  EXPECT_EQ(read_error(folder, text + "], \"a\": 1}"),
            folder.file("scene.json") + ": line 40000: key \"a\" appears twice in the same object");
  EXPECT_EQ(read_error(folder, text + "], oops}"),
            folder.file("scene.json") +
                ": line 40000: malformed JSON: syntax error while parsing "
                "object key - invalid literal; last read: '39999], o'; "
                "expected string literal");
}

TEST(ReleaseJson, EmptiesEveryListAndObject) {
  nlohmann::json document = nlohmann::json::parse(R"({"a": [1, [2, {"b": [3]}]], "c": {"d": 4}})");
  wobble::release_json(document);
  EXPECT_TRUE(document.is_object());
  EXPECT_TRUE(document.empty());
  nlohmann::json list = nlohmann::json::parse("[[1], 2]");
  wobble::release_json(list);
  EXPECT_TRUE(list.is_array() && list.empty());
}

}  // namespace
