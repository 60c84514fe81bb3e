#ifndef WOBBLE_IO_INPUT_FILE_LIMITS_H
#define WOBBLE_IO_INPUT_FILE_LIMITS_H

#include <cstdint>

#include "io/input_file.h"

namespace wobble {

// The largest input files Wobble reads, one per format, and the limits on what a small file can
// ask for. Each is refused at once, from the file's size or its header, with the limit in the
// message. The README's table "Input limits" gives the measurements behind each: a file at the
// limit still loads and runs on a 2-core machine in seconds and well under the machine's memory.
constexpr std::uintmax_t mebibytes = 1024 * 1024;

constexpr FileKind scene_json_file{"a scene (JSON)", 16 * mebibytes};
constexpr FileKind obj_file{"an OBJ mesh", 32 * mebibytes};
constexpr FileKind medit_file{"a MEDIT .mesh file", 16 * mebibytes};
constexpr FileKind tetgen_node_file{"a TetGen .node file", 16 * mebibytes};
constexpr FileKind tetgen_ele_file{"a TetGen .ele file", 16 * mebibytes};
constexpr FileKind png_file{"a PNG texture", 128 * mebibytes};

// An OBJ face of n corners gives n(n-1)/2 springs, so a few bytes can ask for millions.
constexpr long max_face_corners = 256;
// Springs that faces and lines give, counted before a pair shared by faces is merged (what the
// reader must hold at once).
constexpr long max_face_springs = 8'000'000;

// A texture's width and height, each: decoded as RGBA it takes 4 bytes a pixel.
constexpr int max_texture_side = 4096;

}  // namespace wobble

#endif
