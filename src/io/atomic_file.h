#ifndef WOBBLE_IO_ATOMIC_FILE_H
#define WOBBLE_IO_ATOMIC_FILE_H

#include <stdexcept>
#include <string>

namespace wobble {

// Writing an output file failed at run time (disk full, permissions changed mid-run). The
// command line reports it on one line and exits with code 1.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws InputError unless `path` can plausibly be written: its folder exists and is writable,
// and the path itself is not a folder. Called before any long computation, so that a typo in an
// output path is reported at once instead of after the work is done.
void check_output_path(const std::string& path);

// For an option that writes many files into a folder (--record DIR): make `folder` if it is
// missing (not its parents: a typo should not grow a tree of folders), then check that
// `first_file` inside it can be written. Throws InputError naming `option`.
void prepare_output_folder(const std::string& option, const std::string& folder,
                           const std::string& first_file);

// Write `contents` to `path` so that readers only ever see the old file or the complete new one:
// the bytes go to a temporary file in the same folder, are flushed to disk, and the temporary
// file is renamed over `path`. On failure the temporary file is removed and OutputError thrown.
void write_file_atomically(const std::string& path, const std::string& contents);

}  // namespace wobble

#endif
