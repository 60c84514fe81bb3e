#include "io/write_obj.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <vector>

namespace {

struct ParsedObj {
  std::vector<std::vector<double>> v;
  std::vector<std::vector<int>> f, l;
};

ParsedObj parse(const std::string& text) {
  ParsedObj obj;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    std::string word;
    if (tag == "v") {
      obj.v.emplace_back();
      while (words >> word)
        obj.v.back().push_back(std::strtod(word.c_str(), nullptr));
    } else if (tag == "f" || tag == "l") {
      auto& rows = tag == "f" ? obj.f : obj.l;
      rows.emplace_back();
      while (words >> word)
        rows.back().push_back(std::atoi(word.c_str()));
    }
  }
  return obj;
}

TEST(WriteObj, PositionsReadBackBitForBitInOrderThenOneBasedFaces) {
  Eigen::MatrixXd V(3, 3);
  V << 0.1, -2.0 / 3.0, 1e-300, 12345.678901234567, 0.0, -0.0, 1.0 / 7.0, 2.5e17, -1e-5;
  Eigen::MatrixXi F(1, 3);
  F << 0, 2, 1;
  const ParsedObj obj = parse(wobble::obj_text(V, F));
  ASSERT_EQ(obj.v.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(obj.v[i][c], V(i, c)) << i << "," << c;
  }
  ASSERT_EQ(obj.f.size(), 1u);
  EXPECT_EQ(obj.f[0], (std::vector<int>{1, 3, 2}));
  EXPECT_TRUE(obj.l.empty());
}

TEST(WriteObj, NetworkWithoutFacesIsWrittenAsLines) {
  Eigen::MatrixXd V = Eigen::MatrixXd::Zero(3, 3);
  Eigen::MatrixXi E(2, 2);
  E << 0, 1, 1, 2;
  const ParsedObj obj = parse(wobble::obj_text(V, Eigen::MatrixXi(), E));
  EXPECT_TRUE(obj.f.empty());
  ASSERT_EQ(obj.l.size(), 2u);
  EXPECT_EQ(obj.l[1], (std::vector<int>{2, 3}));
}

}  // namespace
