#ifndef WOBBLE_IO_MISSING_TEXTURE_H
#define WOBBLE_IO_MISSING_TEXTURE_H

namespace wobble {

// What a scene file's texture that cannot be read does to the scene: refuses it (the command line
// and the window: the file is wrong), or is noted and left out (the page, where a dropped scene
// may come without the picture it names; the physics does not need it).
enum class MissingTexture { refuse, note };

}  // namespace wobble

#endif
