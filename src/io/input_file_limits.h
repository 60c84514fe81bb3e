#ifndef WOBBLE_IO_INPUT_FILE_LIMITS_H
#define WOBBLE_IO_INPUT_FILE_LIMITS_H

#include <cstddef>
#include <cstdint>

#include "io/input_file.h"

namespace wobble {

// The largest input files Wobble reads, one per format, and the limits on what a small file can
// ask for. Each is refused at once, from the file's size or its header, with the limit in the
// message. docs/scenes.md, "Input files and their limits", gives the measurements behind each: a
// file at the limit still loads and runs on a 2-core machine in seconds and well under the
// machine's memory.
constexpr std::uintmax_t mebibytes = 1024 * 1024;

constexpr FileKind scene_json_file{"a scene (JSON)", 16 * mebibytes};
constexpr FileKind obj_file{"an OBJ mesh", 32 * mebibytes};
constexpr FileKind medit_file{"a MEDIT .mesh file", 16 * mebibytes};
constexpr FileKind tetgen_node_file{"a TetGen .node file", 16 * mebibytes};
constexpr FileKind tetgen_ele_file{"a TetGen .ele file", 16 * mebibytes};
constexpr FileKind png_file{"a PNG texture", 128 * mebibytes};

// What a scene's JSON may hold, checked while it is parsed and before any of it is kept (see
// read_json_file): a parsed document takes 16 bytes a value and more for each key, so without
// these 16 MiB of `0,` or `[]` took 360 to 400 MB just to be refused for a bad value at its end.
// A scene needs a list item a vertex at most (material.vertex_masses, pins): a million items,
// all in one list, take 25 MB while they are parsed. A scene has a few dozen keys (64 colliders
// of 6 keys at most), nests 4 deep, and its longest strings are paths and descriptions.
constexpr long max_json_list_items = 1'000'000;        // items of all lists together
constexpr long max_json_keys = 10'000;                 // keys of all objects together
constexpr long max_json_depth = 64;                    // lists and objects inside each other
constexpr std::size_t max_json_string_bytes = 65'536;  // each string and each key

// An OBJ face of n corners gives n(n-1)/2 springs, so a few bytes can ask for millions.
constexpr long max_face_corners = 256;
// Springs that faces and lines give, counted before a pair shared by faces is merged (what the
// reader must hold at once).
constexpr long max_face_springs = 8'000'000;

// A texture's width and height, each: decoded as RGBA it takes 4 bytes a pixel.
constexpr int max_texture_side = 4096;

}  // namespace wobble

#endif
