#ifndef WOBBLE_IO_OUTPUT_TARGET_H
#define WOBBLE_IO_OUTPUT_TARGET_H

#include <string>

namespace wobble {

// What writing to an output path touches once its symbolic links are followed. Every file Wobble
// writes goes through this (io/atomic_file.h), so that a link is written through, never replaced:
//   new_file      nothing is there yet (a dangling link's target, for example): made atomically;
//   regular_file  replaced atomically by a temporary file renamed over it;
//   in_place      a device or FIFO (/dev/null, a named pipe): opened and written where it is;
//   descriptor    /dev/stdout, /dev/stderr, /dev/fd/N or /proc/self/fd/N: written to this
//                 process's open descriptor N, so `> log` and `| less` get the bytes in order.
struct OutputTarget {
  enum class Kind { new_file, regular_file, in_place, descriptor };
  Kind kind = Kind::new_file;
  std::string path;     // the path written once links are followed (all kinds but descriptor)
  int descriptor = -1;  // for Kind::descriptor
  // The thing written, for finding two outputs that would write the same file: "" for a file
  // yet to be made (then `path`'s folder, made canonical, names it), else device and inode.
  std::string identity;
};

// Follows `path`'s links (at most 40) to what writing it would touch. Returns "" and fills
// `target`, or a reason it cannot be written ("is a folder", "is a link to 'x', whose folder 'y'
// does not exist", "is not open for writing"), for a message that also names the option.
std::string resolve_output(const std::string& path, OutputTarget& target);

// `path` as `resolve_output` found it, for messages: "'out.csv'" or
// "'out.csv' (a link to '/tmp/real.csv')".
std::string shown_output(const std::string& path, const OutputTarget& target);

// Writes all of `contents` to `fd`, again after interruptions and short writes. Returns "" or
// "write failed: REASON".
std::string write_all(int fd, const std::string& contents);

// Writes `contents` in place to a target of kind in_place or descriptor: to the descriptor
// (standard output and error are flushed first, so the bytes follow what was printed), or to the
// device or FIFO opened for writing, waiting up to `fifo_wait_seconds` for a FIFO's reader.
// Returns "" or the reason it failed.
std::string write_in_place(const OutputTarget& target, const std::string& contents,
                           double fifo_wait_seconds = 10.0);

}  // namespace wobble

#endif
