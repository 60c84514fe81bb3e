#ifndef WOBBLE_APP_WEB_PAGE_ARGUMENTS_H
#define WOBBLE_APP_WEB_PAGE_ARGUMENTS_H

#include <string>
#include <vector>

#include "app/cli/color_quantity.h"
#include "sim/settings/simulation_params.h"

namespace wobble {

// The command line a page's address asks for: `query` is the address's query part, as
// `location.search` gives it (e.g. "?scene=flag&k=2000&dt=0.01&iterations=20"), percent-escapes
// and '+' decoded. The result starts with the program's name; then the settings and the view as
// the command line names them (k, dt, iterations, frames: the page stops stepping after that
// many steps, as the window's --frames does; solver, damping, friction,
// self-collision-thickness, camera-yaw, camera-pitch, color-by, every added setting; and the
// switches plots, chebyshev, wind, self-collision, wireframe, springs, points, on when given
// without a value or as 1), and last the scene: the source in `catalog` (scene_catalog()) whose
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

// The view a link carries besides the settings: the colour, the layers and plots switched on,
// and the camera, as ViewCamera::angles gives it (angles in degrees; the scene's own angles, as
// an address without camera keys opens it; times nearer than the framing; whether it was
// panned). The defaults are the view every scene opens with. `faceless`: a scene without faces,
// which shows its springs and points unasked.
struct PageView {
  ColorQuantity color_by = ColorQuantity::material;
  bool wireframe = false, springs = false, points = false, plots = false;
  bool faceless = false;
  double yaw_degrees = 0.0, pitch_degrees = 0.0, zoom = 1.0;
  double scene_yaw_degrees = 0.0, scene_pitch_degrees = 0.0;
  bool panned = false;
};

// The page's "Copy link": the query that opens the scene picker's `scene_label` with `current`'s
// settings, each that differs from `opened` (the scene's own, as an address without keys opens
// it), and `view`'s colour, switches and camera where they differ from the scene's own view
// (color-by, wireframe, springs, points, plots, camera-yaw, camera-pitch and camera-zoom), in the
// keys read_page_address reads; settings in the fewest digits that read back exactly, angles to
// a hundredth of a degree, the zoom to four digits.
std::string page_link_query(const std::string& scene_label, const SimulationParams& opened,
                            const SimulationParams& current, const PageView& view = {});
// What such a link cannot carry (an address only turns switches on; gravity has no key; the
// camera's pan), in words, for the page to say: empty when the link reproduces `current` and
// `view` whole.
std::vector<std::string> page_link_losses(const SimulationParams& opened,
                                          const SimulationParams& current,
                                          const PageView& view = {});
// The keys of a link's query, in words for the page's notice: "scene, k, color-by, springs".
std::string page_link_keys(const std::string& query);

// Whether the address asks for the step benchmark (`bench` among its keys): the page then first
// takes `frames` steps of the scene without drawing (step_positions.h) and leaves their median
// step time (ms) in Module.wobbleBenchStepMs, for scripts/benchmark-web.sh.
bool page_wants_bench(const std::string& query);

}  // namespace wobble

#endif
