#include "read_tetgen.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string_view>
#include <vector>

#include "io/input_file_limits.h"
#include "io/number_word.h"
#include "io/read_text_file.h"
#include "sim/input_error.h"
#include "sim/shapes/tet_mesh.h"

namespace wobble {

namespace {

bool ends_with(const std::string& text, const std::string& ending) {
  return text.size() >= ending.size() &&
         text.compare(text.size() - ending.size(), ending.size(), ending) == 0;
}

// The lines of a TetGen file that hold anything once comments are dropped, split into words as
// they are asked for. Unlike MEDIT, TetGen is line-based: a row is one line, so a short row is an
// error on its line.
class TetgenFile {
 public:
  struct Line {
    int number;
    std::vector<std::string> words;
  };

  TetgenFile(std::string path, const FileKind& kind)
      : path_(std::move(path)), text_(read_text_file(path_, kind)) {
    const std::string_view text(text_);
    int number = 0;
    for (std::size_t start = 0; start < text.size();) {
      const std::size_t newline = text.find('\n', start);
      const std::size_t end = newline == std::string_view::npos ? text.size() : newline;
      const std::string_view line = text.substr(start, end - start);
      const std::string_view content = line.substr(0, line.find('#'));
      ++number;
      if (content.find_first_not_of(" \t\r\v\f") != std::string_view::npos)
        lines_.push_back({number, start, content.size()});
      start = end + 1;
    }
    last_line_ = number;
  }

  // The next line with words on it; `what` names it for the error if the file has ended.
  Line next(const std::string& what) {
    if (next_ == lines_.size())
      fail(std::max(last_line_, 1), "expected " + what + ", but the file ends");
    const Span& span = lines_[next_++];
    Line line{span.number, {}};
    std::istringstream words(text_.substr(span.start, span.size));
    for (std::string word; words >> word;)
      line.words.push_back(word);
    return line;
  }

  // How many lines with words on them are left.
  long lines_left() const { return static_cast<long>(lines_.size() - next_); }

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw InputError(path_ + ": line " + std::to_string(line) + ": " + message);
  }

  // Word `field` of `line` as a whole number; `what` names it for the error. Missing optional
  // header fields take `fallback`.
  long integer(const Line& line, std::size_t field, const std::string& what,
               long fallback = LONG_MIN) const {
    if (field >= line.words.size()) {
      if (fallback != LONG_MIN) return fallback;
      fail(line.number, "expected " + what + ", but the line ends");
    }
    const std::string& word = line.words[field];
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(word.c_str(), &end, 10);
    if (*end != '\0' || end == word.c_str() || errno == ERANGE || value < INT_MIN ||
        value > INT_MAX)
      fail(line.number, "expected " + what + " (a whole number), got '" + word + "'");
    return value;
  }

  double number(const Line& line, std::size_t field, const std::string& what) const {
    const std::string& word = line.words[field];
    double value = 0.0;
    const NumberWord reading = read_number_word(word, value);
    if (reading == NumberWord::underflow) fail(line.number, what + ": " + underflow_message(word));
    if (reading != NumberWord::finite)
      fail(line.number, "expected " + what + " (a finite number), got '" + word + "'");
    return value;
  }

 private:
  // Where a line with words on it lies in the text, comment excluded.
  struct Span {
    int number;
    std::size_t start, size;
  };
  std::string path_;
  std::string text_;
  std::vector<Span> lines_;
  std::size_t next_ = 0;
  int last_line_ = 0;
};

}  // namespace

std::string tetgen_base(const std::string& path) {
  std::string base = path;
  for (const char* ending : {".node", ".ele"}) {
    if (ends_with(base, ending)) {
      base.resize(base.size() - std::strlen(ending));
      break;
    }
  }
  return base;
}

TetMeshFile read_tetgen(const std::string& path) {
  const std::string base = tetgen_base(path);
  TetMeshFile mesh;

  TetgenFile node(base + ".node", tetgen_node_file);
  const TetgenFile::Line node_header = node.next("the header '#points dimension ...'");
  const long points = node.integer(node_header, 0, "the number of points");
  const long dimension = node.integer(node_header, 1, "the dimension", 3);
  const long point_attributes = node.integer(node_header, 2, "the number of attributes", 0);
  const long markers = node.integer(node_header, 3, "the number of boundary markers", 0);
  if (points < 1)
    node.fail(node_header.number, "expected at least one point, got " + std::to_string(points));
  if (dimension != 3)
    node.fail(node_header.number, "expected dimension 3, got " + std::to_string(dimension));
  if (point_attributes < 0 || point_attributes > 1000)
    node.fail(node_header.number,
              "expected 0 to 1000 attributes, got " + std::to_string(point_attributes));
  if (markers != 0 && markers != 1)
    node.fail(node_header.number,
              "expected 0 or 1 boundary markers, got " + std::to_string(markers));
  const std::size_t point_width = 4 + point_attributes + markers;
  long first_index = 0;
  // Each row is one line, so a count above the lines left fails in next() before the loop
  // writes past them; sizing by what is there keeps a corrupt count out of the allocator.
  mesh.V.resize(std::min(points, node.lines_left()), 3);
  for (long i = 0; i < points; ++i) {
    const TetgenFile::Line line =
        node.next(std::to_string(points) + " points, found " + std::to_string(i));
    if (line.words.size() < point_width) {
      node.fail(line.number, "expected " + std::to_string(point_width) +
                                 " numbers (index, x, y, z, attributes, marker), got " +
                                 std::to_string(line.words.size()));
    }
    const long index = node.integer(line, 0, "a point index");
    if (i == 0) {
      if (index != 0 && index != 1)
        node.fail(line.number,
                  "expected the first point to be numbered 0 or 1, got " + std::to_string(index));
      first_index = index;
    } else if (index != first_index + i) {
      node.fail(line.number, "expected point number " + std::to_string(first_index + i) +
                                 " (points are numbered consecutively), got " +
                                 std::to_string(index));
    }
    for (int c = 0; c < 3; ++c)
      mesh.V(i, c) = node.number(line, 1 + c, "a coordinate");
    for (std::size_t field = 4; field < point_width; ++field)
      node.number(line, field, "an attribute or marker");
  }

  TetgenFile ele(base + ".ele", tetgen_ele_file);
  const TetgenFile::Line ele_header = ele.next("the header '#tetrahedra nodes ...'");
  const long tets = ele.integer(ele_header, 0, "the number of tetrahedra");
  const long nodes = ele.integer(ele_header, 1, "the number of nodes per tetrahedron", 4);
  const long tet_attributes = ele.integer(ele_header, 2, "the number of attributes", 0);
  if (tets < 1)
    ele.fail(ele_header.number, "expected at least one tetrahedron, got " + std::to_string(tets));
  if (nodes != 4 && nodes != 10)
    ele.fail(ele_header.number,
             "expected 4 or 10 nodes per tetrahedron, got " + std::to_string(nodes));
  if (tet_attributes < 0 || tet_attributes > 1000)
    ele.fail(ele_header.number,
             "expected 0 to 1000 attributes, got " + std::to_string(tet_attributes));
  const std::size_t tet_width = 1 + nodes + tet_attributes;
  const long last_index = first_index + points - 1;
  mesh.T.resize(std::min(tets, ele.lines_left()), 4);  // as for the points
  for (long t = 0; t < tets; ++t) {
    const TetgenFile::Line line =
        ele.next(std::to_string(tets) + " tetrahedra, found " + std::to_string(t));
    if (line.words.size() < tet_width) {
      ele.fail(line.number, "expected " + std::to_string(tet_width) + " numbers (index, " +
                                std::to_string(nodes) + " nodes, attributes), got " +
                                std::to_string(line.words.size()));
    }
    ele.integer(line, 0, "a tetrahedron index");
    // Every node must exist, though only the four corners (listed first) are kept.
    for (long c = 0; c < nodes; ++c) {
      const long index = ele.integer(line, 1 + c, "a point index");
      if (index < first_index || index > last_index) {
        ele.fail(line.number, "expected point indices from " + std::to_string(first_index) +
                                  " to " + std::to_string(last_index) + ", got " +
                                  std::to_string(index));
      }
      if (c < 4) mesh.T(t, c) = static_cast<int>(index - first_index);
    }
    for (std::size_t field = 1 + nodes; field < tet_width; ++field)
      ele.number(line, field, "an attribute");
    const Eigen::Vector3d a = mesh.V.row(mesh.T(t, 0)), b = mesh.V.row(mesh.T(t, 1)),
                          c = mesh.V.row(mesh.T(t, 2)), d = mesh.V.row(mesh.T(t, 3));
    if (tetrahedron_is_flat(a, b, c, d)) {
      ele.fail(line.number,
               "expected a tetrahedron with volume, but its corners are repeated or coplanar");
    }
  }
  return mesh;
}

}  // namespace wobble
