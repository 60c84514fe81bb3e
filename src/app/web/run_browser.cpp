#include "app/web/run_browser.h"

// glad first: GLFW must not include a GL header of its own.
#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <emscripten.h>
#include <emscripten/html5.h>
#include <imgui.h>

#include <algorithm>
#include <exception>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli/scene_catalog.h"
#include "app/viewer/frame_loop.h"
#include "app/viewer/viewer.h"
#include "app/web/page_arguments.h"
#include "app/web/page_host.h"
#include "app/web/step_positions.h"
#include "io/load_scene.h"
#include "platform/glfw_window.h"

namespace wobble {

namespace {

// What WebGL 2 lacks of the desktop's GL 3.3 core, and the renderer calls: glad leaves it null
// on a GL ES 3.0 context. Polygon modes (the wireframe over the surface) draw filled. (The
// springs' colour table, a buffer texture, makes no call in the page: spring_color_table.h.)
void GLAD_API_PTR no_polygon_mode(GLenum, GLenum) {}

void fill_missing_gl_functions() {
  if (glad_glPolygonMode == nullptr) glad_glPolygonMode = no_polygon_mode;
}

// Everything a frame needs, kept alive after main returns.
struct BrowserApp {
  Viewer viewer;
  std::unique_ptr<GlfwWindow> window;
  std::unique_ptr<ImGuiSession> ui;
  std::unique_ptr<PageHost> host;
  FrameMeters meters;  // the panel's fps, UI frame time and real-time factor
  CommandLine command;
  bool bench = false;       // ?bench: measure the step once the page shows the scene
  int quiet_frames = 0;     // frames drawn since the last input
  double last_drawn = 0.0;  // when the last frame was drawn (s, seconds_now)
};

BrowserApp* the_app = nullptr;  // for the page's calls into the program (wobble_pinch)

// A file the viewer wrote into the page's memory, handed to the browser as a download under its
// own name (the page has no folder of its own to write into).
void offer_download(const std::string& path) {
  EM_ASM(
      {
        var path = UTF8ToString($0);
        var name = path.substring(path.lastIndexOf('/') + 1);
        try {
          var link = document.createElement('a');
          var cwd = FS.cwd();
          var full = path.charAt(0) == '/'
                         ? path
                         : (cwd == '/' ? '' : cwd) + '/' +
                               (path.indexOf('./') == 0 ? path.substring(2) : path);
          link.href = URL.createObjectURL(new Blob([FS.readFile(full)]));
          link.download = name;
          document.body.appendChild(link);
          link.click();
          setTimeout(
              function() {
                URL.revokeObjectURL(link.href);
                link.remove();
              },
              10000);
          Module.wobbleDownloads = (Module.wobbleDownloads || []).concat([name]);
        } catch (error) {
          console.error('wobble: could not offer ' + name + ' as a download: ' + error + ' ' +
                        (error.errno || ''));
        }
      },
      path.c_str());
}

// The browser's wheel over the canvas, in notches (page_wheel_notches); the page itself does not
// scroll. (Emscripten's GLFW passes the raw deltaY on, about 100 a notch and the other way.)
EM_BOOL on_wheel(int /*type*/, const EmscriptenWheelEvent* event, void* host) {
  static_cast<PageHost*>(host)->wheel(page_wheel_notches(event->deltaY, event->deltaMode));
  return EM_TRUE;
}

// ?bench: the same steps as the node and native runs of scripts/benchmark-web.sh (step_positions),
// taken once the page shows the scene and says what it is doing; the result is said on the page
// and left in Module.wobbleBenchStepMs for the script.
void run_bench(BrowserApp& app) {
  std::ostringstream json;
  step_positions(app.command, json);
  const double median_ms = EM_ASM_DOUBLE(
      {
        Module.wobbleBenchStepMs = JSON.parse(UTF8ToString($0)).step_ms_median;
        return Module.wobbleBenchStepMs;
      },
      json.str().c_str());
  std::ostringstream told;
  told << "bench: a step of " << app.viewer.session().scene().name << " takes " << std::fixed
       << std::setprecision(2) << median_ms << " ms (the median of "
       << app.command.frames.value_or(60) << " steps, one thread)";
  app.viewer.files().tell(told.str());
  std::cerr << "wobble: " << told.str() << "\n";
}

void frame_or_report(void* app_pointer) {
  BrowserApp& app = *static_cast<BrowserApp*>(app_pointer);
  try {
    // The bench blocks the page for seconds: the scene and the notice saying so are shown first.
    if (app.bench && app.host->frames_drawn() == 2) {
      app.bench = false;
      run_bench(app);
    }
    // With nothing new to show (paused, at the address's step limit or by the user, and no
    // input for a few frames) the page draws the same picture only every idle_redraw_seconds,
    // as the window waits for input: a page left open in a lecture keeps no core busy (it took
    // nearly two cores drawing the same frame in software at the browser's rate). ImGui settles
    // a click or a hover over a few frames, so the page only idles after settle_frames frames
    // without input; the periodic frame shows a notice that timed out.
    constexpr int settle_frames = 3;
    constexpr double idle_redraw_seconds = 1.0;
    const double now = seconds_now();
    if (app.host->input_waiting()) {
      app.quiet_frames = 0;
    } else if (app.quiet_frames >= settle_frames && !app.viewer.animating() &&
               now - app.last_drawn < idle_redraw_seconds) {
      return;
    }
    draw_frame(app.viewer, *app.host, app.meters, FramePolicy(), app.host->scale());
    app.host->report(app.viewer);
    app.last_drawn = now;
    ++app.quiet_frames;
  } catch (const std::exception& error) {
    std::cerr << "wobble: error: " << error.what() << "\n";
  }
}

// "Copy link": an address that opens the scene with its settings as they are now, relative to
// the scene's own (as the catalogue opens it), told on the page and put on the clipboard.
void copy_link(BrowserApp& app) {
  const std::string name = app.viewer.session().scene().name;
  const std::string& source = app.viewer.session().scene_source();
  const std::vector<std::string> catalog = scene_catalog();
  if (std::find(catalog.begin(), catalog.end(), source) == catalog.end()) {
    app.viewer.files().tell("Copy link: " + name +
                            " came from a file on this computer, which an address cannot open; "
                            "Save scene gives the file to share");
    return;
  }
  const SimulationParams opened = load_scene(source).params;
  const SimulationParams& current = app.viewer.session().simulation().params();
  PageView view;
  view.color_by = app.viewer.panel().color_by();
  const ViewLayers layers = app.viewer.panel().layers();
  view.wireframe = layers.wireframe;
  view.springs = layers.springs;
  view.points = layers.points;
  view.plots = app.viewer.session().plots_open();
  view.faceless = app.viewer.panel().faceless();
  const ViewCamera::Angles angles = app.viewer.drawing().camera_angles();
  view.yaw_degrees = angles.yaw_degrees;
  view.pitch_degrees = angles.pitch_degrees;
  view.zoom = angles.zoom;
  view.scene_yaw_degrees = angles.scene_yaw_degrees;
  view.scene_pitch_degrees = angles.scene_pitch_degrees;
  view.panned = angles.panned;
  const std::string query = page_link_query(scene_label(source), opened, current, view);
  // The query is percent-encoded: no quote or backslash reaches the script.
  const char* link =
      emscripten_run_script_string(("Module.wobbleCopyLink('" + query + "')").c_str());
  const bool copied = EM_ASM_INT({ return navigator.clipboard && window.isSecureContext ? 1 : 0; });
  std::string told = std::string(copied ? "link copied: " : "link (this page cannot copy): ") +
                     (link != nullptr ? link : query) + "; it keeps " + page_link_keys(query);
  const std::vector<std::string> lost = page_link_losses(opened, current, view);
  for (std::size_t i = 0; i < lost.size(); ++i)
    told += (i == 0 ? " (an address cannot carry " : ", ") + lost[i] +
            (i + 1 == lost.size() ? ")" : "");
  app.viewer.files().tell(told);
}

}  // namespace

void run_browser(const CommandLine& command, const std::vector<std::string>& messages, bool bench) {
  static std::unique_ptr<BrowserApp> app;  // lives for the page's life
  double css_width = 0.0, css_height = 0.0;
  emscripten_get_element_css_size("#canvas", &css_width, &css_height);
  // The page's buttons, its keys, and on a phone's screen, narrower than the panel, the panel
  // folded to its title bar (a tap opens it), so that the scene shows.
  PageSettings page;
  page.actions = {[] { EM_ASM({ Module.wobblePickFiles(); }); }, [] { copy_link(*the_app); }};
  page.help = page_bindings();
  page.panel_folded = css_width > 0 && css_width < 600;
  app.reset(
      new BrowserApp{open_viewer(command, page), nullptr, nullptr, nullptr, {}, command, bench});
  the_app = app.get();
  app->viewer.files().show_notices(true);
  if (command.frames) app->viewer.session().set_step_limit(*command.frames);
  const std::string title = "Wobble: " + app->viewer.session().scene().name;
  app->window =
      std::make_unique<GlfwWindow>(css_width > 0 ? static_cast<int>(css_width) : 1280,
                                   css_height > 0 ? static_cast<int>(css_height) : 720, title);
  fill_missing_gl_functions();
  app->ui = std::make_unique<ImGuiSession>(app->window->handle(), page_pixel_ratio());
  app->host = std::make_unique<PageHost>(*app->window, *app->ui);
  // The panel moves by its title bar only: a finger's sideways drag on it (index.html) drags a
  // slider, never the panel.
  ImGui::GetIO().ConfigWindowsMoveFromTitleBarOnly = true;
  // The wheel from the browser's event, which says its unit; GLFW's path (ImGui's and the
  // window's callbacks) is turned off.
  glfwSetScrollCallback(app->window->handle(), nullptr);
  emscripten_set_wheel_callback("#canvas", app->host.get(), EM_TRUE, on_wheel);
  app->viewer.files().set_written(offer_download);
  print_notes(app->viewer.session().scene(), std::cerr);
  std::string told;
  for (const std::string& message : messages) {
    app->viewer.files().tell(message);
    std::cerr << "wobble: " << message << "\n";
    told += (told.empty() ? "" : "\n") + message;
  }
  // For the page's tests (tests/web): what the page told, and the scene it opened.
  EM_ASM(
      {
        Module.wobbleMessages = UTF8ToString($0);
        Module.wobbleScene = UTF8ToString($1);
      },
      told.c_str(), app->viewer.session().scene().name.c_str());
  app->viewer.drawing().attach_renderer();
  // 0 frames a second: the browser's own rate (requestAnimationFrame); do not simulate an
  // infinite loop, so main returns and the page keeps running.
  emscripten_set_main_loop_arg(frame_or_report, app.get(), 0, 0);
}

}  // namespace wobble

// For the page's tests (tests/web/page_files_in_check.py): the scene shown, its steps and its
// positions, as JSON in Module.wobblePositions (17 significant digits, as step_positions writes).
extern "C" EMSCRIPTEN_KEEPALIVE void wobble_report_positions() {
  if (wobble::the_app == nullptr) return;
  const wobble::Viewer& viewer = wobble::the_app->viewer;
  const Eigen::MatrixXd& positions = viewer.session().simulation().positions();
  std::ostringstream out;
  out << std::setprecision(17) << "{\"scene\": \"" << viewer.session().scene().name
      << "\", \"steps\": " << viewer.session().simulation().steps_taken() << ", \"positions\": [";
  for (Eigen::Index i = 0; i < positions.rows(); ++i) {
    out << (i == 0 ? "" : ", ") << "[" << positions(i, 0) << ", " << positions(i, 1) << ", "
        << positions(i, 2) << "]";
  }
  out << "]}";
  EM_ASM({ Module.wobblePositions = UTF8ToString($0); }, out.str().c_str());
}

// The page's swipe on the panel (index.html): the finger `pixels` (CSS) farther up.
extern "C" EMSCRIPTEN_KEEPALIVE void wobble_scroll_panel(double pixels) {
  if (wobble::the_app != nullptr && wobble::the_app->host)
    wobble::the_app->host->swipe_panel(pixels);
}

// The page's pinch (index.html): the fingers' spread grown `ratio` times since the last call.
extern "C" EMSCRIPTEN_KEEPALIVE void wobble_pinch(double ratio) {
  if (wobble::the_app != nullptr && wobble::the_app->host) wobble::the_app->host->pinch(ratio);
}
