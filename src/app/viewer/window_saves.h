#ifndef WOBBLE_APP_VIEWER_WINDOW_SAVES_H
#define WOBBLE_APP_VIEWER_WINDOW_SAVES_H

#include <string>

namespace wobble {

// A file name for a save from the window that does not replace an earlier one: `stem-NNNN.ext`
// in `folder`, NNNN the first number from 1 whose file does not exist yet (e.g.
// wobble-cloth-0001.png).
std::string unused_file_name(const std::string& folder, const std::string& stem,
                             const std::string& extension);

}  // namespace wobble

#endif
