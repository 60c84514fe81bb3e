#include "read_obj.h"

#include <tiny_obj_loader.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

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

// What tinyobjloader is given, and where each element came from.
struct Statements {
  // The file with only its `v`, `vt`, `f` and `l` lines, the others left empty so that line
  // numbers stay the same. tinyobjloader 2.0.0rc10 drops the `l` elements of a group that has
  // no faces, and a file without groups is one group, so no line is lost.
  std::string kept;
  std::vector<int> face_lines, line_lines;  // line number of every `f`, every `l`
  std::vector<double> positions;            // x y z of every `v`
  std::vector<double> texcoords;            // u v of every `vt` (v = 0 when not given)
  long springs = 0;  // springs the faces and lines give, before shared pairs are merged
};

// tinyobjloader turns "abc" into 0 and "3x" into 3 without a word, so each line it will read is
// checked here first, and the message can say which line is wrong.
Statements check_statements(const std::string& path, const std::string& text) {
  Statements statements;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    const std::vector<std::string> words = split(line, " \t\r");
    const std::string keyword = words.empty() ? "" : words[0];
    const std::string at = path + ": line " + std::to_string(number) + ": ";
    if (keyword == "v" || keyword == "vt") {
      const std::size_t required = keyword == "v" ? 3 : 1;
      if (words.size() < required + 1) {
        throw InputError(at + "`" + keyword + "` has " + std::to_string(words.size() - 1) +
                         " coordinates, expected " + (keyword == "v" ? "x y z" : "u [v]"));
      }
      double values[3] = {0.0, 0.0, 0.0};
      // strtod rounds correctly; tinyobjloader 2.0.0rc10's own number reader is off by up to an
      // ulp (0.75 reads as 0.75000000000000011), which would keep a mesh from reading back bit
      // for bit what write_obj wrote, or what the course's reader reads. So coordinates are
      // taken from here.
      for (std::size_t w = 1; w < words.size() && w <= 3; ++w) {
        const NumberWord reading = read_number_word(words[w], values[w - 1]);
        if (reading == NumberWord::underflow) {
          throw InputError(at + "coordinate " + underflow_message(words[w]));
        }
        if (reading != NumberWord::finite) {
          throw InputError(at + "coordinate '" + words[w] + "' is not a finite number");
        }
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
      for (std::size_t w = 1; w < words.size(); ++w) {
        if (!is_corner(words[w])) {
          throw InputError(at + "'" + words[w] +
                           "' is not a vertex reference, expected v, v/vt, v//vn or v/vt/vn "
                           "with non-zero integer indices");
        }
      }
      (keyword == "f" ? statements.face_lines : statements.line_lines).push_back(number);
    } else {
      statements.kept += '\n';
      continue;
    }
    // Single spaces: tinyobjloader misreads an `l` line with two spaces after the keyword.
    for (std::size_t w = 0; w < words.size(); ++w)
      statements.kept += (w == 0 ? "" : " ") + words[w];
    statements.kept += '\n';
  }
  return statements;
}

// Every `f` element as tinyobjloader's callback reader passes it (the ObjReader drops faces of
// two vertices), with the number of `v` and `vt` before it, which negative indices count from.
struct RawFace {
  std::vector<tinyobj::index_t> corners;
  int vertices_before = 0;
  int texcoords_before = 0;
};

struct FaceCollector {
  int vertices = 0;
  int texcoords = 0;
  std::vector<RawFace> faces;
};

std::vector<RawFace> collect_faces(const std::string& path, const std::string& kept) {
  tinyobj::callback_t callback;
  callback.vertex_cb = [](void* user, tinyobj::real_t, tinyobj::real_t, tinyobj::real_t,
                          tinyobj::real_t) { ++static_cast<FaceCollector*>(user)->vertices; };
  callback.texcoord_cb = [](void* user, tinyobj::real_t, tinyobj::real_t, tinyobj::real_t) {
    ++static_cast<FaceCollector*>(user)->texcoords;
  };
  callback.index_cb = [](void* user, tinyobj::index_t* indices, int count) {
    auto& collector = *static_cast<FaceCollector*>(user);
    collector.faces.push_back({std::vector<tinyobj::index_t>(indices, indices + count),
                               collector.vertices, collector.texcoords});
  };
  FaceCollector collector;
  std::istringstream stream(kept);
  std::string warning, error;
  if (!tinyobj::LoadObjWithCallback(stream, callback, &collector, nullptr, &warning, &error)) {
    throw InputError(path + ": not a readable OBJ file (" + error + ")");
  }
  return std::move(collector.faces);
}

// The 0-based index of a raw OBJ index (1-based, or negative counting back from `before`),
// checked against the `count` elements there are of the kind `what` (a plural noun).
int resolve(int raw, int before, int count, const std::string& what, const std::string& at) {
  const int index = raw > 0 ? raw - 1 : before + raw;
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

}  // namespace

ObjMesh read_obj(const std::string& path) {
  const Statements statements = check_statements(path, read_text_file(path, obj_file));

  tinyobj::ObjReaderConfig config;
  config.triangulate = false;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(statements.kept, "", config)) {
    throw InputError(path + ": " + one_line(reader.Error()));
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const int vertex_count = static_cast<int>(statements.positions.size() / 3);
  const int texcoord_count = static_cast<int>(statements.texcoords.size() / 2);
  if (attrib.vertices.size() != statements.positions.size() ||
      attrib.texcoords.size() != statements.texcoords.size()) {
    throw std::logic_error(path + ": tinyobjloader and the line check disagree on the count");
  }
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

  const std::vector<RawFace> raw_faces = collect_faces(path, statements.kept);
  for (std::size_t f = 0; f < raw_faces.size(); ++f) {
    const RawFace& raw = raw_faces[f];
    const std::string at = path + ": line " + std::to_string(statements.face_lines.at(f)) + ": ";
    std::vector<int> face;
    for (const tinyobj::index_t& corner : raw.corners) {
      const int v = resolve(corner.vertex_index, raw.vertices_before, vertex_count, "vertices", at);
      for (int earlier : face) {
        if (earlier == v) {
          throw InputError(at + "the face uses vertex " + std::to_string(v + 1) +
                           " twice, expected distinct vertices");
        }
      }
      face.push_back(v);
      // The callback reader leaves a missing texture index at 0, which no valid index is.
      if (corner.texcoord_index == 0) continue;
      const int t = resolve(corner.texcoord_index, raw.texcoords_before, texcoord_count,
                            "texture coordinates", at);
      any_uv = true;
      if (has_uv[v]) continue;  // the first face to give a vertex its uv wins
      has_uv[v] = 1;
      uv.row(v) << statements.texcoords[2 * t], statements.texcoords[2 * t + 1];
    }
    mesh.faces.push_back(std::move(face));
  }

  std::size_t polyline = 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::size_t offset = 0;
    for (const int count : shape.lines.num_line_vertices) {
      const std::string at =
          path + ": line " + std::to_string(statements.line_lines.at(polyline++)) + ": ";
      for (int c = 0; c < count; ++c) {
        // tinyobjloader has already made this index 0-based; it checks no range for lines.
        const int v = shape.lines.indices[offset + c].vertex_index;
        if (v < 0 || v >= vertex_count) {
          throw InputError(at + "a vertex index refers to none of the " +
                           std::to_string(vertex_count) + " vertices, expected 1 to " +
                           std::to_string(vertex_count) + " or a negative index counting back");
        }
        if (c == 0) continue;
        const int previous = shape.lines.indices[offset + c - 1].vertex_index;
        if (previous == v) {
          throw InputError(at + "a segment joins vertex " + std::to_string(v + 1) +
                           " to itself, expected two distinct vertices");
        }
        mesh.faces.push_back({previous, v});
      }
      offset += static_cast<std::size_t>(count);
    }
  }
  if (mesh.faces.empty()) {
    throw InputError(path + ": no faces or lines, expected `f` or `l` lines joining the vertices");
  }
  if (any_uv) mesh.uv = std::move(uv);
  return mesh;
}

}  // namespace wobble
