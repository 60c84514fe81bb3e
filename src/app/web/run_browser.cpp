#include "app/web/run_browser.h"

// glad first: GLFW must not include a GL header of its own.
#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <emscripten.h>
#include <emscripten/html5.h>
#include <imgui.h>

#include <exception>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/cli/scene_catalog.h"
#include "app/viewer/frame_loop.h"
#include "app/viewer/viewer.h"
#include "app/web/page_arguments.h"
#include "platform/glfw_window.h"

namespace wobble {

namespace {

// What WebGL 2 lacks of the desktop's GL 3.3 core, and the renderer calls: glad leaves these
// null on a GL ES 3.0 context. Polygon modes (the wireframe over the surface) draw filled, and
// the springs' colour table (a buffer texture) stays empty; see shaders/es/spring_colors.frag.
void GLAD_API_PTR no_polygon_mode(GLenum, GLenum) {}
void GLAD_API_PTR no_texture_buffer(GLenum, GLenum, GLuint) {}

void fill_missing_gl_functions() {
  if (glad_glPolygonMode == nullptr) glad_glPolygonMode = no_polygon_mode;
  if (glad_glTexBuffer == nullptr) glad_glTexBuffer = no_texture_buffer;
}

double seconds_now() {
  return 1e-3 * emscripten_get_now();
}

// The canvas fills the page (index.html's style sheet); its drawing buffer follows that size.
void follow_page_size(GlfwWindow& window) {
  double css_width = 0.0, css_height = 0.0;
  emscripten_get_element_css_size("#canvas", &css_width, &css_height);
  int width = 0, height = 0;
  window.window_size(width, height);
  const int wanted_width = static_cast<int>(css_width),
            wanted_height = static_cast<int>(css_height);
  if (wanted_width > 0 && wanted_height > 0 && (wanted_width != width || wanted_height != height)) {
    glfwSetWindowSize(window.handle(), wanted_width, wanted_height);
  }
}

// The page as draw_frame's host: emscripten's GLFW for input, the browser's clock, steps on this
// thread, and the canvas the browser shows once the frame returns.
class PageHost : public FrameHost {
 public:
  explicit PageHost(GlfwWindow& window) : window_(window) {}
  std::vector<InputEvent> poll(const Viewer& /*viewer*/, const FrameMeters& /*meters*/) override {
    follow_page_size(window_);
    std::vector<InputEvent> events = window_.poll_events();
    // The wheel, read by on_wheel from the browser's own event, in notches: to the camera and
    // to ImGui's panel (before its new frame) alike.
    for (const double notches : wheel_) {
      InputEvent event;
      event.type = InputEvent::Type::scroll;
      event.y = notches;
      events.push_back(event);
      ImGui::GetIO().MouseWheel += static_cast<float>(notches);
    }
    wheel_.clear();
    return events;
  }
  void wheel(double notches) {
    if (notches != 0.0) wheel_.push_back(notches);
  }
  // Copied into the page's file system by emscripten's GLFW.
  std::vector<std::string> take_dropped_paths() override { return window_.take_dropped_paths(); }
  double now() const override { return seconds_now(); }
  void sizes(int& width, int& height, Eigen::Vector2f& window) override {
    window_.window_size(width, height);
    window = Eigen::Vector2f(static_cast<float>(width), static_cast<float>(height));
    width_ = width;
    height_ = height;
  }
  void new_platform_frame() override { ImGuiSession::new_glfw_frame(); }
  void before_panel() override {
    // A phone's screen is narrower than the panel: it opens folded (its title bar; a tap opens
    // it), so that the scene shows. The panel is the first window build_ui begins.
    if (frames_drawn_ == 0 && width_ < 600) ImGui::SetNextWindowCollapsed(true, ImGuiCond_Once);
  }
  bool advance(Viewer& viewer, double now) override {
    constexpr double frame_seconds = 1.0 / 60.0;
    return viewer.exchange(now, frame_seconds);
  }
  void set_title(const std::string& title) override {
    if (title != title_) window_.set_title(title_ = title);
  }
  void bind_target() override { glBindFramebuffer(GL_FRAMEBUFFER, 0); }
  void present(Viewer& viewer, bool drawn) override {
    // The PNG button (and F12) read the canvas before the browser shows it, as the window reads
    // its back buffer; the file is then offered as a download (offer_download).
    const int width = width_, height = height_;
    viewer.write_window_files(drawn, [width, height] { return read_shown_frame(width, height); });
    // For the page and its tests (tests/web/page_check.py): frames drawn, and the steps they
    // show.
    ++frames_drawn_;
    EM_ASM(
        {
          Module.wobbleFrames = $0;
          Module.wobbleSteps = $1;
        },
        frames_drawn_, static_cast<double>(viewer.shown_steps()));
    EM_ASM({ Module.wobbleCameraDistance = $0; }, static_cast<double>(viewer.camera().distance));
  }

 private:
  GlfwWindow& window_;
  std::string title_;
  int width_ = 0, height_ = 0;
  long frames_drawn_ = 0;
  std::vector<double> wheel_;  // notches since the last poll
};

// Everything a frame needs, kept alive after main returns.
struct BrowserApp {
  Viewer viewer;
  std::unique_ptr<GlfwWindow> window;
  std::unique_ptr<ImGuiSession> ui;
  std::unique_ptr<PageHost> host;
  FrameMeters meters;  // the panel's fps, UI frame time and real-time factor
};

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

void frame_or_report(void* app_pointer) {
  BrowserApp& app = *static_cast<BrowserApp*>(app_pointer);
  try {
    draw_frame(app.viewer, *app.host, app.meters, 1.0f);
  } catch (const std::exception& error) {
    std::cerr << "wobble: error: " << error.what() << "\n";
  }
}

}  // namespace

void run_browser(const CommandLine& command, const std::vector<std::string>& messages) {
  static std::unique_ptr<BrowserApp> app;  // lives for the page's life
  app.reset(new BrowserApp{open_viewer(command), nullptr, nullptr, nullptr, {}});
  app->viewer.show_notices(true);
  if (command.frames) app->viewer.set_step_limit(*command.frames);
  double css_width = 0.0, css_height = 0.0;
  emscripten_get_element_css_size("#canvas", &css_width, &css_height);
  const std::string title = "Wobble: " + app->viewer.scene().name;
  app->window =
      std::make_unique<GlfwWindow>(css_width > 0 ? static_cast<int>(css_width) : 1280,
                                   css_height > 0 ? static_cast<int>(css_height) : 720, title);
  fill_missing_gl_functions();
  app->ui = std::make_unique<ImGuiSession>(app->window->handle(), "#version 300 es", 1.0f);
  app->host = std::make_unique<PageHost>(*app->window);
  // The wheel from the browser's event, which says its unit; GLFW's path (ImGui's and the
  // window's callbacks) is turned off.
  glfwSetScrollCallback(app->window->handle(), nullptr);
  emscripten_set_wheel_callback("#canvas", app->host.get(), EM_TRUE, on_wheel);
  app->viewer.set_file_written(offer_download);
  app->viewer.set_help(page_bindings());
  print_notes(app->viewer.scene(), std::cerr);
  std::string told;
  for (const std::string& message : messages) {
    app->viewer.tell(message);
    std::cerr << "wobble: " << message << "\n";
    told += (told.empty() ? "" : "\n") + message;
  }
  // For the page's tests (tests/web): what the page told, and the scene it opened.
  EM_ASM(
      {
        Module.wobbleMessages = UTF8ToString($0);
        Module.wobbleScene = UTF8ToString($1);
      },
      told.c_str(), app->viewer.scene().name.c_str());
  app->viewer.attach_renderer();
  // 0 frames a second: the browser's own rate (requestAnimationFrame); do not simulate an
  // infinite loop, so main returns and the page keeps running.
  emscripten_set_main_loop_arg(frame_or_report, app.get(), 0, 0);
}

}  // namespace wobble
