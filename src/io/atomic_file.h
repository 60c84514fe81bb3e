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

// Throws InputError naming `option` (e.g. "--export-obj") unless `path` can be written, its links
// followed (io/output_target.h): a device, a FIFO or an open descriptor (/dev/stdout) is written
// in place; a file, or a new file in an existing folder, needs a temporary file made beside it
// right now, which finds names too long for the filesystem, folders that take no files and
// read-only disks. The probe file is removed at once, so nothing is left. Called before any long
// computation, so that a typo in an output path is reported at once instead of after the work.
void check_output_path(const std::string& option, const std::string& path);

// For an option that writes many files into a folder (--record DIR): throws InputError naming
// `option` unless `folder` is a folder in which `first_file` passes check_output_path, or is
// missing but could be made in an existing parent (not its parents: a typo should not grow a
// tree of folders). Creates nothing (a probe folder is made and removed), so that bad input
// found later leaves no empty folder; make_output_folder makes it once everything is checked.
void check_output_folder(const std::string& option, const std::string& folder,
                         const std::string& first_file);

// Make `folder` if it is missing. Throws OutputError if it cannot be made.
void make_output_folder(const std::string& folder);

// The one writer of every file Wobble writes. `path`'s links are followed and written through,
// never replaced. A device, a FIFO or an open descriptor (/dev/stdout, /dev/fd/N) is written in
// place. A file is written so that readers only ever see the old file or the complete new one:
// the bytes go to a temporary file in the same folder (PATH.tmp-XXXXXX), are flushed to disk,
// the temporary file is renamed over the file, and the folder is flushed to disk too, so that
// the rename survives a power cut. A replaced file keeps its permission bits; a new one gets
// 0666 less the umask. On failure the temporary file is removed and OutputError thrown.
void write_output_file(const std::string& path, const std::string& contents);

// From now on, SIGTERM and SIGINT first remove the temporary file being written (if any), then
// end the program as they would have. The handler only calls unlink and raise, which are
// async-signal-safe; the temporary file's name waits for it in a static buffer.
void remove_temporary_file_on_termination();

}  // namespace wobble

#endif
