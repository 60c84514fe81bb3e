#include "read_text_file.h"

namespace wobble {

std::string read_text_file(const std::string& path, const FileKind& kind) {
  return without_byte_order_mark(read_input_file(path, kind));
}

}  // namespace wobble
