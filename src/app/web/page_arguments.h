#ifndef WOBBLE_APP_WEB_PAGE_ARGUMENTS_H
#define WOBBLE_APP_WEB_PAGE_ARGUMENTS_H

#include <string>
#include <vector>

namespace wobble {

// The command line a page's address asks for: `query` is the address's query part, as
// `location.search` gives it (e.g. "?scene=flag&k=2000&dt=0.01&iterations=20"), percent-escapes
// and '+' decoded. The result starts with the program's name; then --k, --dt, --iterations and
// --frames (the page stops stepping after that many steps, as the window's --frames does),
// --plots for `plots`, and last the scene: the source in `catalog` (scene_catalog()) whose
// picker label (scene_label) is the `scene` value, or the value itself. Keys it does not know are
// left out, so an address never reaches an option that writes files. The values are checked by
// parse_command_line.
std::vector<std::string> page_arguments(const std::string& query,
                                        const std::vector<std::string>& catalog);

// The same, with what the address got wrong said instead of silently dropped: each key whose
// value the command line refuses, an unknown key, and a scene that is none of the catalogue's,
// one line each as the command line words it, naming the address's key ("address: k: expected a
// positive finite number, got 'abc'"; "address: scene: no scene 'flg' (cloth, jelly, ...)").
// The arguments keep every key that is right, so a typo in one setting still opens the scene
// with the others; a scene that is not found opens the default scene.
struct PageRequest {
  std::vector<std::string> arguments;
  std::vector<std::string> refusals;
};
PageRequest read_page_address(const std::string& query, const std::vector<std::string>& catalog);

// A browser wheel event as notches of a desktop wheel, positive away from the user (zoom in, the
// panel up), as GLFW counts them on the desktop: the browser's deltaY is positive towards the
// user and in pixels (about 100 a mouse's notch; a trackpad sends many small ones, each a share
// of a notch), lines (3 a notch) or pages (one a notch), by `delta_mode` 0, 1 or 2.
double page_wheel_notches(double delta_y, unsigned long delta_mode);

// Whether the address asks for the step benchmark (`bench` among its keys): the page then first
// takes `frames` steps of the scene without drawing (step_positions.h) and leaves their median
// step time (ms) in Module.wobbleBenchStepMs, for scripts/benchmark-web.sh.
bool page_wants_bench(const std::string& query);

}  // namespace wobble

#endif
