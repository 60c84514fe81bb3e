#ifndef WOBBLE_TESTS_APP_PARSE_WORDS_H
#define WOBBLE_TESTS_APP_PARSE_WORDS_H

#include <gtest/gtest.h>

#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli/command_line.h"

namespace wobble::testing {

// The command line `wobble WORDS...` as parse_command_line reads it; a failed test (and a
// default CommandLine) when it answers the request itself.
inline CommandLine parse_words(std::vector<std::string> words) {
  words.insert(words.begin(), "wobble");
  std::vector<const char*> argv;
  for (const std::string& word : words)
    argv.push_back(word.c_str());
  std::ostringstream out;
  const std::optional<CommandLine> command =
      parse_command_line(static_cast<int>(argv.size()), argv.data(), out);
  EXPECT_TRUE(command.has_value());
  return command.value_or(CommandLine{});
}

}  // namespace wobble::testing

#endif
