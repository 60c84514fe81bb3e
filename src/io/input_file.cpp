#include "input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "sim/input_error.h"
#include "sim/input_limits.h"

namespace wobble {

namespace {

// Why stat or open failed, in words that say what to fix.
std::string reason_for(int error) {
  switch (error) {
    case ENOENT:
      return "no such file";
    case ENOTDIR:
      return "cannot be reached: a part of the path is not a folder";
    case ELOOP:
      return "cannot be reached: a symbolic link loop (or too many links in a row)";
    case ENAMETOOLONG:
      return "cannot be reached: the name is longer than the filesystem allows";
    case EACCES:
      return "cannot be reached: permission denied (a folder on the way or the file itself)";
    default:
      return std::string("cannot be read: ") + std::strerror(error);
  }
}

// Why a file with this status is not one to read, or "".
std::string status_problem(const struct stat& status, const FileKind& kind) {
  const mode_t type = status.st_mode & S_IFMT;
  if (type == S_IFDIR) return "is a folder";
  if (type == S_IFIFO) return "is a FIFO (named pipe), not a regular file";
  if (type == S_IFCHR) return "is a character device, not a regular file";
  if (type == S_IFBLK) return "is a block device, not a regular file";
  if (type == S_IFSOCK) return "is a socket, not a regular file";
  if (type != S_IFREG) return "is not a regular file";
  const auto size = static_cast<std::uintmax_t>(status.st_size);
  if (size > kind.max_bytes) {
    return "is " + describe_bytes(size) + ", above Wobble's limit of " +
           describe_bytes(kind.max_bytes) + " for " + kind.what;
  }
  return "";
}

std::string expecting(const std::string& problem, const FileKind& kind) {
  // A size message already names the kind of file.
  if (problem.find("Wobble's limit") != std::string::npos) return problem;
  return problem + ", expected " + kind.what;
}

}  // namespace

std::string input_file_problem(const std::string& path, const FileKind& kind) {
  struct stat status;
  if (::stat(path.c_str(), &status) != 0) return expecting(reason_for(errno), kind);
  const std::string problem = status_problem(status, kind);
  return problem.empty() ? problem : expecting(problem, kind);
}

bool input_file_is_missing(const std::string& path) {
  struct stat status;
  return ::stat(path.c_str(), &status) != 0 && errno == ENOENT;
}

InputFile::InputFile(const std::string& path, const FileKind& kind) : path_(path), kind_(kind) {
  // Checked before opening: opening a FIFO without O_NONBLOCK waits for a writer, and opening
  // some devices has effects of its own.
  const std::string problem = input_file_problem(path, kind);
  if (!problem.empty()) throw InputError(path + ": " + problem);
  descriptor_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (descriptor_ < 0) throw InputError(path + ": " + expecting(reason_for(errno), kind));
  // The path may name something else by now; what counts is what was opened.
  struct stat status;
  if (::fstat(descriptor_, &status) != 0) {
    const int error = errno;
    ::close(descriptor_);
    throw InputError(path + ": " + expecting(reason_for(error), kind));
  }
  const std::string opened_problem = status_problem(status, kind);
  if (!opened_problem.empty()) {
    ::close(descriptor_);
    throw InputError(path + ": " + expecting(opened_problem, kind));
  }
  size_ = static_cast<std::uintmax_t>(status.st_size);
}

InputFile::~InputFile() {
  if (descriptor_ >= 0) ::close(descriptor_);
}

std::size_t InputFile::read(char* buffer, std::size_t size) {
  for (;;) {
    const ssize_t got = ::read(descriptor_, buffer, size);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0)
      throw InputError(path_ + ": could not read the file (" + std::strerror(errno) + ")");
    if (got == 0 && size > 0) at_end_ = true;
    read_ += static_cast<std::uintmax_t>(got);
    if (read_ > kind_.max_bytes) {
      throw InputError(path_ + ": grew past Wobble's limit of " + describe_bytes(kind_.max_bytes) +
                       " for " + kind_.what + " while it was read");
    }
    return static_cast<std::size_t>(got);
  }
}

void InputFile::skip(long bytes) {
  if (::lseek(descriptor_, bytes, SEEK_CUR) < 0) {
    throw InputError(path_ + ": could not read the file (" + std::strerror(errno) + ")");
  }
}

void InputFile::rewind() {
  if (::lseek(descriptor_, 0, SEEK_SET) < 0) {
    throw InputError(path_ + ": could not read the file (" + std::strerror(errno) + ")");
  }
  read_ = 0;
  at_end_ = false;
}

std::string InputFile::read_rest() {
  std::string contents;
  // One byte more than the size, so that the read that finds the end needs no reallocation.
  contents.resize(static_cast<std::size_t>(size_) + 1);
  std::size_t filled = 0;
  for (;;) {
    if (filled == contents.size()) contents.resize(contents.size() + 65536);
    const std::size_t got = read(contents.data() + filled, contents.size() - filled);
    if (got == 0) break;
    filled += got;
  }
  contents.resize(filled);
  return contents;
}

std::string read_input_file(const std::string& path, const FileKind& kind) {
  InputFile file(path, kind);
  return file.read_rest();
}

std::string without_byte_order_mark(std::string text) {
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
  return text;
}

std::string describe_bytes(std::uintmax_t bytes) {
  std::string text = with_thousands_separators(static_cast<long>(bytes)) + " bytes";
  const std::uintmax_t mebibyte = 1024 * 1024;
  if (bytes >= mebibyte && bytes % mebibyte == 0) {
    text += " (" + std::to_string(bytes / mebibyte) + " MiB)";
  }
  return text;
}

}  // namespace wobble
