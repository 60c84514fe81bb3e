#ifndef WOBBLE_IO_INPUT_FILE_H
#define WOBBLE_IO_INPUT_FILE_H

#include <cstddef>
#include <cstdint>
#include <string>

namespace wobble {

// What a reader expects of a file it reads: a name for messages ("an OBJ mesh") and the largest
// size it takes, in bytes. The limits themselves are in io/input_file_limits.h.
struct FileKind {
  const char* what;
  std::uintmax_t max_bytes;
};

// Why `path` cannot be read as a file of `kind`, or "" when it can: it must name a regular
// file (not a folder, FIFO, device or socket) of at most kind.max_bytes bytes. The reason reads
// after the path: "is a FIFO (named pipe), not a regular file, expected an OBJ mesh", "no such
// file, expected ...", "cannot be reached: a symbolic link loop, expected ...". Looks only at the
// file's status; opens nothing, so it never blocks.
std::string input_file_problem(const std::string& path, const FileKind& kind);

// Whether input_file_problem's answer only says the file is not there (no such file, or a
// dangling symbolic link): callers that try other meanings of a name first (a built-in scene)
// ask this.
bool input_file_is_missing(const std::string& path);

// A file opened for reading, after the checks of input_file_problem, in a way that cannot block:
// its status is checked before opening, it is opened with O_NONBLOCK, and the status of the
// opened descriptor is checked again, so a file swapped for a FIFO in between is still refused.
// Throws InputError "PATH: REASON" otherwise.
class InputFile {
 public:
  InputFile(const std::string& path, const FileKind& kind);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  // Up to `size` bytes into `buffer`; 0 at the end. Throws InputError on a read error, or when
  // the file has grown past the limit since it was opened.
  std::size_t read(char* buffer, std::size_t size);
  // Move the reading position by `bytes` (may be negative) or to the start.
  void skip(long bytes);
  void rewind();
  // The rest of the file, read once.
  std::string read_rest();

  bool at_end() const { return at_end_; }        // whether a read has found the end
  std::uintmax_t size() const { return size_; }  // at opening
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  FileKind kind_;
  int descriptor_ = -1;
  std::uintmax_t size_ = 0;
  std::uintmax_t read_ = 0;  // bytes read so far, to stop a file that grows while it is read
  bool at_end_ = false;
};

// The whole of the file at `path`, read once, after InputFile's checks.
std::string read_input_file(const std::string& path, const FileKind& kind);

// `text` without a leading UTF-8 byte-order mark (EF BB BF), which editors on Windows write.
std::string without_byte_order_mark(std::string text);

// `bytes` as a readable size: "33,554,432 bytes (32 MiB)".
std::string describe_bytes(std::uintmax_t bytes);

}  // namespace wobble

#endif
