#include "sim/input_error.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using wobble::escape_control_characters;
using wobble::InputError;

TEST(InputError, EscapesControlCharactersSoNothingPrintsRaw) {
  EXPECT_EQ(escape_control_characters("a\nb\rc\td"), "a\\nb\\rc\\td");
  EXPECT_EQ(escape_control_characters(std::string("x\0y", 3)), "x\\x00y");
  EXPECT_EQ(escape_control_characters("\x1b[31m\x7f"), "\\x1b[31m\\x7f");
  // UTF-8 and backslashes stay, so escaping twice changes nothing.
  EXPECT_EQ(escape_control_characters("m/s² C:\\x"), "m/s² C:\\x");
  const std::string once = escape_control_characters(std::string("k\0\n", 3));
  EXPECT_EQ(escape_control_characters(once), once);
}

// what() is a C string: a NUL byte kept raw would end the message before what was expected.
TEST(InputError, AMessageWithANulByteStillSaysWhatWasExpected) {
  const std::string coordinate(
      "1\0"
      "5",
      3);
  const InputError error("mesh.obj: line 2: got '" + coordinate + "', expected a finite number");
  EXPECT_EQ(std::string(error.what()), "mesh.obj: line 2: got '1\\x005', expected a finite number");
}

TEST(InputError, OneLineTurnsALibrarysLineBreaksIntoSpaces) {
  EXPECT_EQ(wobble::one_line("first\nsecond\t third \n"), "first second  third");
  EXPECT_EQ(wobble::one_line(std::string("a\0b", 3)), "a\\x00b");
}

}  // namespace
