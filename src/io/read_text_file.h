#ifndef WOBBLE_IO_READ_TEXT_FILE_H
#define WOBBLE_IO_READ_TEXT_FILE_H

#include <string>

namespace wobble {

// The whole of the file at `path`, as bytes. Throws InputError "PATH: no such file, expected
// WHAT" when it is not a regular file (missing, or a folder), and "PATH: could not read the file"
// when reading fails. `what` names what the file should have been ("an OBJ mesh").
std::string read_text_file(const std::string& path, const std::string& what);

}  // namespace wobble

#endif
