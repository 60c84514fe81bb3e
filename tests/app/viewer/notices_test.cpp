// Notices on their own: shown for a few seconds, oldest first, at most a few at once.
#include "app/viewer/notices.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

TEST(Notices, ShownForAFewSecondsOldestFirstAndAtMostAFew) {
  wobble::Notices notices;
  EXPECT_TRUE(notices.shown(0.0).empty());
  notices.post("wrote a.png", 10.0);
  notices.post("wrote b.obj", 11.0);
  EXPECT_EQ(notices.shown(11.5), (std::vector<std::string>{"wrote a.png", "wrote b.obj"}));
  // a.png's time is up first.
  const double past_a = 10.0 + wobble::Notices::shown_seconds + 0.1;
  EXPECT_EQ(notices.shown(past_a), std::vector<std::string>{"wrote b.obj"});
  EXPECT_TRUE(notices.shown(11.0 + wobble::Notices::shown_seconds + 0.1).empty());

  for (int i = 0; i < 6; ++i)
    notices.post("notice " + std::to_string(i), 20.0 + 0.1 * i);
  const std::vector<std::string> shown = notices.shown(21.0);
  ASSERT_EQ(shown.size(), wobble::Notices::most_shown);
  EXPECT_EQ(shown.back(), "notice 5") << "the newest stay";
  EXPECT_EQ(shown.front(), "notice 2");
}
