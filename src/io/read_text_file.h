#ifndef WOBBLE_IO_READ_TEXT_FILE_H
#define WOBBLE_IO_READ_TEXT_FILE_H

#include <string>

#include "io/input_file.h"

namespace wobble {

// The text of the file at `path`, read once, without a leading UTF-8 byte-order mark. Throws
// InputError "PATH: REASON, expected WHAT" when it is not a regular file of at most
// kind.max_bytes (missing, unreachable, a folder, a FIFO, a device, too large; see InputFile),
// and "PATH: could not read the file (...)" when reading fails.
std::string read_text_file(const std::string& path, const FileKind& kind);

}  // namespace wobble

#endif
