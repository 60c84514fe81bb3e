#include "read_medit_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <vector>

#include "io/input_file_limits.h"
#include "io/number_word.h"
#include "io/read_text_file.h"
#include "sim/input_error.h"
#include "sim/input_limits.h"
#include "sim/shapes/tet_mesh.h"

namespace wobble {

namespace {

// Row widths (numbers per row, in 3-D) of the sections that Wobble reads past without using.
struct SkippedSection {
  const char* keyword;
  int width;
};
constexpr SkippedSection kSkippedSections[] = {
    {"Edges", 3},
    {"Triangles", 4},
    {"Quadrilaterals", 5},
    {"Hexahedra", 9},
    {"Prisms", 7},
    {"Pyramids", 6},
    {"Corners", 1},
    {"Ridges", 1},
    {"RequiredVertices", 1},
    {"RequiredEdges", 1},
    {"RequiredTriangles", 1},
    {"RequiredQuadrilaterals", 1},
    {"RequiredTetrahedra", 1},
    {"Normals", 3},
    {"NormalAtVertices", 2},
    {"Tangents", 3},
    {"TangentAtVertices", 2},
    {"NormalAtTriangleVertices", 3},
};

bool same_keyword(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

// The words of a MEDIT file with the line each starts on. Newlines carry no meaning in the
// format, so the reader asks for words and uses lines only to point at errors.
class Words {
 public:
  Words(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) {}

  // The next word, or an empty view at the end of the file.
  std::string_view next() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        ++pos_;
      } else if (c == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n')
          ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++pos_;
      } else {
        break;
      }
    }
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_])) &&
           text_[pos_] != '#')
      ++pos_;
    return std::string_view(text_).substr(start, pos_ - start);
  }

  // The next word, which `what` says must be there.
  std::string_view need(const std::string& what) {
    const std::string_view word = next();
    if (word.empty()) fail("expected " + what + ", but the file ends");
    return word;
  }

  double number(const std::string& what) {
    const std::string word(need(what));
    double value = 0.0;
    const NumberWord reading = read_number_word(word, value);
    if (reading == NumberWord::malformed) fail("expected " + what + ", got '" + word + "'");
    if (reading == NumberWord::not_finite)
      fail("expected " + what + " (finite), got '" + word + "'");
    if (reading == NumberWord::underflow) fail(what + ": " + underflow_message(word));
    return value;
  }

  long integer(const std::string& what) {
    const std::string word(need(what));
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(word.c_str(), &end, 10);
    if (*end != '\0' || end == word.c_str() || errno == ERANGE || value < INT_MIN ||
        value > INT_MAX)
      fail("expected " + what + " (a whole number), got '" + word + "'");
    return value;
  }

  long count(const std::string& keyword, long limit = INT_MAX) {
    const long n = integer("the number of " + keyword);
    if (n < 0) fail("expected a non-negative number of " + keyword + ", got " + std::to_string(n));
    if (n > limit) {
      fail("expected at most " + with_thousands_separators(limit) + " " + keyword +
           " (Wobble's limit), got " + std::to_string(n));
    }
    return n;
  }

  [[noreturn]] void fail(const std::string& message, int line = 0) const {
    throw InputError(path_ + ": line " + std::to_string(line > 0 ? line : line_) + ": " + message);
  }
  int line() const { return line_; }

 private:
  std::string path_;
  std::string text_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

std::string row_name(const char* section, long row) {
  return std::string(section) + " row " + std::to_string(row + 1);
}

}  // namespace

TetMeshFile read_medit_mesh(const std::string& path) {
  Words words(path, read_text_file(path, medit_file));

  // Rows go into vectors that grow as they are read rather than into matrices sized by the
  // section's count, so that a corrupt count fails at the file's end, not in the allocator.
  std::vector<double> coordinates;  // x y z per vertex
  std::vector<int> corners;         // a b c d per tetrahedron, 1-based until checked
  std::vector<int> tet_lines;       // the line of each tetrahedron, to point at it later
  bool have_vertices = false, have_tetrahedra = false;
  for (std::string_view keyword = words.next(); !keyword.empty(); keyword = words.next()) {
    if (same_keyword(keyword, "End")) break;
    if (same_keyword(keyword, "MeshVersionFormatted")) {
      words.integer("a MeshVersionFormatted version");
    } else if (same_keyword(keyword, "Dimension")) {
      const long dimension = words.integer("the Dimension");
      if (dimension != 3) words.fail("expected Dimension 3, got " + std::to_string(dimension));
    } else if (same_keyword(keyword, "Vertices")) {
      if (have_vertices) words.fail("expected one Vertices section, found a second");
      have_vertices = true;
      const long n = words.count("Vertices", max_input_vertices);
      for (long i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c)
          coordinates.push_back(words.number("a coordinate in " + row_name("Vertices", i)));
        words.number("a reference number in " + row_name("Vertices", i));
      }
    } else if (same_keyword(keyword, "Tetrahedra")) {
      if (have_tetrahedra) words.fail("expected one Tetrahedra section, found a second");
      have_tetrahedra = true;
      const long n = words.count("Tetrahedra", max_input_tetrahedra);
      for (long t = 0; t < n; ++t) {
        for (int c = 0; c < 4; ++c) {
          corners.push_back(
              static_cast<int>(words.integer("a vertex index in " + row_name("Tetrahedra", t))));
          if (c == 0) tet_lines.push_back(words.line());
        }
        words.number("a reference number in " + row_name("Tetrahedra", t));
      }
    } else {
      const auto* skipped =
          std::find_if(std::begin(kSkippedSections), std::end(kSkippedSections),
                       [&](const SkippedSection& s) { return same_keyword(keyword, s.keyword); });
      if (skipped == std::end(kSkippedSections)) {
        words.fail("expected a MEDIT keyword (Vertices, Tetrahedra, Triangles, End, ...), got '" +
                   std::string(keyword) + "'");
      }
      const long n = words.count(skipped->keyword);
      for (long row = 0; row < n; ++row) {
        for (int c = 0; c < skipped->width; ++c)
          words.number("a number in " + row_name(skipped->keyword, row));
      }
    }
  }

  if (!have_vertices) words.fail("expected a Vertices section");
  if (corners.empty()) words.fail("expected a Tetrahedra section with at least one tetrahedron");
  using RowMajorXd = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
  using RowMajorXi = Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>;
  TetMeshFile mesh;
  mesh.V = Eigen::Map<const RowMajorXd>(coordinates.data(), coordinates.size() / 3, 3);
  mesh.T = Eigen::Map<const RowMajorXi>(corners.data(), corners.size() / 4, 4);
  const long vertex_count = mesh.V.rows();
  for (Eigen::Index t = 0; t < mesh.T.rows(); ++t) {
    for (int c = 0; c < 4; ++c) {
      const int index = mesh.T(t, c);
      if (index < 1 || index > vertex_count) {
        words.fail("expected vertex indices from 1 to " + std::to_string(vertex_count) + " in " +
                       row_name("Tetrahedra", t) + ", got " + std::to_string(index),
                   tet_lines[t]);
      }
      mesh.T(t, c) = index - 1;
    }
  }
  for (Eigen::Index t = 0; t < mesh.T.rows(); ++t) {
    const Eigen::Vector3d a = mesh.V.row(mesh.T(t, 0)), b = mesh.V.row(mesh.T(t, 1)),
                          c = mesh.V.row(mesh.T(t, 2)), d = mesh.V.row(mesh.T(t, 3));
    if (tetrahedron_is_flat(a, b, c, d)) {
      words.fail("expected a tetrahedron with volume in " + row_name("Tetrahedra", t) +
                     ", but its corners are repeated or coplanar",
                 tet_lines[t]);
    }
  }
  return mesh;
}

}  // namespace wobble
