#include "read_obj.h"

#include <cstdlib>
#include <sstream>

#include "io/input_file_limits.h"
#include "io/number_word.h"
#include "read_text_file.h"
#include "sim/input_error.h"
#include "sim/input_limits.h"

namespace wobble {

namespace {

std::vector<std::string> split(const std::string& text, const char* separators) {
  std::vector<std::string> words;
  std::size_t start = text.find_first_not_of(separators);
  while (start != std::string::npos) {
    const std::size_t end = text.find_first_of(separators, start);
    words.push_back(text.substr(start, end == std::string::npos ? end : end - start));
    start = end == std::string::npos ? end : text.find_first_not_of(separators, end);
  }
  return words;
}

// One part of an index triple: a non-zero integer, optionally negative, that fits in an int.
bool is_index(const std::string& part) {
  const std::size_t sign = !part.empty() && part[0] == '-' ? 1 : 0;
  const std::size_t digits = part.size() - sign;
  if (digits == 0 || digits > 9) return false;
  if (part.find_first_not_of("0123456789", sign) != std::string::npos) return false;
  return std::atoi(part.c_str()) != 0;
}

// `v`, `v/vt`, `v//vn` or `v/vt/vn`.
bool is_corner(const std::string& word) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t slash; (slash = word.find('/', start)) != std::string::npos; start = slash + 1)
    parts.push_back(word.substr(start, slash - start));
  parts.push_back(word.substr(start));
  if (parts.size() > 3 || parts[0].empty() || !is_index(parts[0])) return false;
  if (parts.size() == 2) return is_index(parts[1]);
  if (parts.size() == 3) return (parts[1].empty() || is_index(parts[1])) && is_index(parts[2]);
  return true;
}

// One corner of an `f` element or one vertex of an `l` polyline, as written: the vertex index
// and the texture-coordinate index (0: none), each 1-based or negative.
struct RawCorner {
  int vertex = 0;
  int texcoord = 0;
};

// One `f` or `l` line, with the number of `v` and `vt` lines before it, which negative indices
// count back from (a positive index may name a vertex that comes later in the file).
struct RawElement {
  std::vector<RawCorner> corners;
  int vertices_before = 0;
  int texcoords_before = 0;
  int line = 0;
};

// Every `v`, `vt`, `f` and `l` line, checked word by word so that the message can say which line
// is wrong; other statements (groups, materials, normals, points) are skipped.
struct Statements {
  std::vector<double> positions;  // x y z of every `v`
  std::vector<double> texcoords;  // u v of every `vt` (v = 0 when not given)
  std::vector<RawElement> faces, lines;
  long springs = 0;  // springs the faces and lines give, before shared pairs are merged
};

// The corner `word` (already checked by is_corner): `v`, `v/vt`, `v//vn` or `v/vt/vn`. Normal
// indices are not used.
RawCorner read_corner(const std::string& word) {
  RawCorner corner;
  corner.vertex = std::atoi(word.c_str());
  const std::size_t slash = word.find('/');
  if (slash != std::string::npos && slash + 1 < word.size() && word[slash + 1] != '/') {
    corner.texcoord = std::atoi(word.c_str() + slash + 1);
  }
  return corner;
}

Statements read_statements(const std::string& path, const std::string& text) {
  Statements statements;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    // A comment runs from `#` to the end of the line, after any statement as on a line of its
    // own; what is left must be the statement and nothing else.
    const std::vector<std::string> words = split(line.substr(0, line.find('#')), " \t\r");
    const std::string keyword = words.empty() ? "" : words[0];
    const std::string at = path + ": line " + std::to_string(number) + ": ";
    if (keyword == "v" || keyword == "vt") {
      const std::size_t required = keyword == "v" ? 3 : 1;
      // `v x y z [w]` or `v x y z r g b` (a colour, as some programs write), `vt u [v [w]]`.
      const std::size_t most = keyword == "v" ? 6 : 3;
      if (words.size() < required + 1 || words.size() > most + 1) {
        throw InputError(at + "`" + keyword + "` has " + std::to_string(words.size() - 1) +
                         " coordinates, expected " +
                         (keyword == "v" ? "x y z (or x y z w, or x y z r g b)" : "u [v] [w]") +
                         ", then at most a # comment");
      }
      // strtod rounds correctly, so a mesh reads back bit for bit what write_obj wrote, and what
      // the course's reader reads. The numbers past the first three are checked, not kept.
      double values[3] = {0.0, 0.0, 0.0};
      for (std::size_t w = 1; w < words.size(); ++w) {
        double value = 0.0;
        const NumberWord reading = read_number_word(words[w], value);
        if (reading == NumberWord::underflow) {
          throw InputError(at + "coordinate " + underflow_message(words[w]));
        }
        if (reading != NumberWord::finite) {
          throw InputError(at + "coordinate '" + words[w] + "' is not a finite number");
        }
        if (w <= 3) values[w - 1] = value;
      }
      auto& values_of_kind = keyword == "v" ? statements.positions : statements.texcoords;
      values_of_kind.insert(values_of_kind.end(), values, values + (keyword == "v" ? 3 : 2));
    } else if (keyword == "f" || keyword == "l") {
      if (words.size() < 3) {
        throw InputError(at + "`" + keyword + "` lists " + std::to_string(words.size() - 1) +
                         " vertices, expected at least 2");
      }
      // Every pair of a face's corners is a spring: n corners, n(n-1)/2 springs.
      const long corners = static_cast<long>(words.size()) - 1;
      if (keyword == "f" && corners > max_face_corners) {
        throw InputError(at + "the face has " + std::to_string(corners) +
                         " corners, above Wobble's limit of " + std::to_string(max_face_corners) +
                         " (a face of n corners gives n(n-1)/2 springs)");
      }
      statements.springs += keyword == "f" ? corners * (corners - 1) / 2 : corners - 1;
      if (statements.springs > max_face_springs) {
        throw InputError(at + "the faces and lines so far give " +
                         with_thousands_separators(statements.springs) +
                         " springs, above Wobble's limit of " +
                         with_thousands_separators(max_face_springs) +
                         " (a face of n corners gives n(n-1)/2 springs)");
      }
      RawElement element;
      element.vertices_before = static_cast<int>(statements.positions.size() / 3);
      element.texcoords_before = static_cast<int>(statements.texcoords.size() / 2);
      element.line = number;
      for (std::size_t w = 1; w < words.size(); ++w) {
        if (!is_corner(words[w])) {
          throw InputError(at + "'" + words[w] +
                           "' is not a vertex reference, expected v, v/vt, v//vn or v/vt/vn "
                           "with non-zero integer indices");
        }
        element.corners.push_back(read_corner(words[w]));
      }
      (keyword == "f" ? statements.faces : statements.lines).push_back(std::move(element));
    }
  }
  return statements;
}

// The 0-based index of a raw OBJ index: 1-based, or negative counting back from the `before`
// elements of its kind that come before its line. Not range-checked.
int zero_based(int raw, int before) {
  return raw > 0 ? raw - 1 : before + raw;
}

// zero_based(raw, before), checked against the `count` elements there are of the kind `what`
// (a plural noun).
int resolve(int raw, int before, int count, const std::string& what, const std::string& at) {
  const int index = zero_based(raw, before);
  const std::string given = at + "index " + std::to_string(raw) + " ";
  if (count == 0) throw InputError(given + "given, but the file has no " + what);
  if (index < 0 || index >= count) {
    const std::string backward =
        before > 0 ? " or -1 to -" + std::to_string(before) + " counting back" : "";
    throw InputError(given + "refers to none of the " + std::to_string(count) + " " + what +
                     ", expected 1 to " + std::to_string(count) + backward);
  }
  return index;
}

std::string line_at(const std::string& path, const RawElement& element) {
  return path + ": line " + std::to_string(element.line) + ": ";
}

}  // namespace

ObjMesh read_obj(const std::string& path) {
  const Statements statements = read_statements(path, read_text_file(path, obj_file));
  const int vertex_count = static_cast<int>(statements.positions.size() / 3);
  const int texcoord_count = static_cast<int>(statements.texcoords.size() / 2);
  if (vertex_count == 0) throw InputError(path + ": no vertices, expected `v x y z` lines");

  ObjMesh mesh;
  mesh.V.resize(vertex_count, 3);
  for (int i = 0; i < vertex_count; ++i) {
    for (int c = 0; c < 3; ++c)
      mesh.V(i, c) = statements.positions[3 * i + c];
  }
  std::vector<char> has_uv(vertex_count, 0);
  Eigen::MatrixXd uv = Eigen::MatrixXd::Zero(vertex_count, 2);
  bool any_uv = false;

  for (const RawElement& raw : statements.faces) {
    const std::string at = line_at(path, raw);
    std::vector<int> face;
    for (const RawCorner& corner : raw.corners) {
      const int v = resolve(corner.vertex, raw.vertices_before, vertex_count, "vertices", at);
      for (int earlier : face) {
        if (earlier == v) {
          throw InputError(at + "the face uses vertex " + std::to_string(v + 1) +
                           " twice, expected distinct vertices");
        }
      }
      face.push_back(v);
      if (corner.texcoord == 0) continue;
      const int t =
          resolve(corner.texcoord, raw.texcoords_before, texcoord_count, "texture coordinates", at);
      any_uv = true;
      if (has_uv[v]) continue;  // the first face to give a vertex its uv wins
      has_uv[v] = 1;
      uv.row(v) << statements.texcoords[2 * t], statements.texcoords[2 * t + 1];
    }
    mesh.faces.push_back(std::move(face));
  }

  // Every segment of every polyline, after the faces; a polyline's texture indices are unused.
  for (const RawElement& raw : statements.lines) {
    const std::string at = line_at(path, raw);
    int previous = -1;
    for (const RawCorner& corner : raw.corners) {
      const int v = zero_based(corner.vertex, raw.vertices_before);
      if (v < 0 || v >= vertex_count) {
        throw InputError(at + "a vertex index refers to none of the " +
                         std::to_string(vertex_count) + " vertices, expected 1 to " +
                         std::to_string(vertex_count) + " or a negative index counting back");
      }
      if (previous == v) {
        throw InputError(at + "a segment joins vertex " + std::to_string(v + 1) +
                         " to itself, expected two distinct vertices");
      }
      if (previous >= 0) mesh.faces.push_back({previous, v});
      previous = v;
    }
  }
  if (mesh.faces.empty()) {
    throw InputError(path + ": no faces or lines, expected `f` or `l` lines joining the vertices");
  }
  if (any_uv) mesh.uv = std::move(uv);
  return mesh;
}

}  // namespace wobble
