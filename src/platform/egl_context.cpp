#include "egl_context.h"

// EGL is opened at run time (dlopen), not linked: a machine without libEGL.so.1 still runs the
// window, and --headless there says what is missing instead of the program not starting.
#define EGL_EGL_PROTOTYPES 0
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>
#include <glad/gl.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <type_traits>

#include "sim/input_error.h"

namespace wobble {

namespace {

// The EGL functions used here, from libEGL.so.1 (glvnd's, which picks the vendor: Mesa or
// NVIDIA). Opened once; `missing` says why when it cannot be.
struct EglLibrary {
  PFNEGLGETPROCADDRESSPROC get_proc_address = nullptr;
  PFNEGLQUERYSTRINGPROC query_string = nullptr;
  PFNEGLGETERRORPROC get_error = nullptr;
  PFNEGLINITIALIZEPROC initialize = nullptr;
  PFNEGLTERMINATEPROC terminate = nullptr;
  PFNEGLCHOOSECONFIGPROC choose_config = nullptr;
  PFNEGLBINDAPIPROC bind_api = nullptr;
  PFNEGLCREATECONTEXTPROC create_context = nullptr;
  PFNEGLMAKECURRENTPROC make_current = nullptr;
  PFNEGLDESTROYCONTEXTPROC destroy_context = nullptr;
  std::string missing;

  EglLibrary() {
    void* library = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
    if (library == nullptr) {
      missing = "libEGL.so.1 is not installed (Debian: libegl1, with libegl-mesa0 for Mesa)";
      return;
    }
    const auto load = [&](auto& function, const char* name) {
      function =
          reinterpret_cast<std::remove_reference_t<decltype(function)>>(dlsym(library, name));
      if (function == nullptr && missing.empty())
        missing = std::string("libEGL.so.1 lacks ") + name;
    };
    load(get_proc_address, "eglGetProcAddress");
    load(query_string, "eglQueryString");
    load(get_error, "eglGetError");
    load(initialize, "eglInitialize");
    load(terminate, "eglTerminate");
    load(choose_config, "eglChooseConfig");
    load(bind_api, "eglBindAPI");
    load(create_context, "eglCreateContext");
    load(make_current, "eglMakeCurrent");
    load(destroy_context, "eglDestroyContext");
  }
};

const EglLibrary& egl() {
  static const EglLibrary library;
  return library;
}

std::string egl_error_name(EGLint code) {
  switch (code) {
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    default: {
      char text[32];
      std::snprintf(text, sizeof text, "EGL error 0x%04X", code);
      return text;
    }
  }
}

bool has_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t length = std::strlen(name);
  for (const char* at = std::strstr(list, name); at != nullptr; at = std::strstr(at + 1, name)) {
    const bool starts = at == list || at[-1] == ' ';
    if (starts && (at[length] == ' ' || at[length] == '\0')) return true;
  }
  return false;
}

// A display on the first EGL device, or EGL_NO_DISPLAY with `failure` saying why.
EGLDisplay device_display(const char* client_extensions, std::string& failure) {
  if (!has_extension(client_extensions, "EGL_EXT_platform_device") ||
      !has_extension(client_extensions, "EGL_EXT_device_enumeration")) {
    failure = "EGL_EXT_platform_device is not offered";
    return EGL_NO_DISPLAY;
  }
  const auto query_devices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(egl().get_proc_address("eglQueryDevicesEXT"));
  const auto platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      egl().get_proc_address("eglGetPlatformDisplayEXT"));
  EGLDeviceEXT devices[8];
  EGLint count = 0;
  if (query_devices == nullptr || platform_display == nullptr ||
      query_devices(8, devices, &count) != EGL_TRUE || count < 1) {
    failure = "eglQueryDevicesEXT found no device";
    return EGL_NO_DISPLAY;
  }
  const EGLDisplay display = platform_display(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
  if (display == EGL_NO_DISPLAY) {
    failure = "eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT) failed (" +
              egl_error_name(egl().get_error()) + ")";
  }
  return display;
}

EGLDisplay surfaceless_display(const char* client_extensions, std::string& failure) {
  if (!has_extension(client_extensions, "EGL_MESA_platform_surfaceless")) {
    failure = "EGL_MESA_platform_surfaceless is not offered";
    return EGL_NO_DISPLAY;
  }
  const auto platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      egl().get_proc_address("eglGetPlatformDisplayEXT"));
  const EGLDisplay display =
      platform_display == nullptr
          ? EGL_NO_DISPLAY
          : platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) {
    failure = "eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA) failed (" +
              egl_error_name(egl().get_error()) + ")";
  }
  return display;
}

// Initialize `display` and make a GL 3.3 core context current on it without a surface.
EGLContext make_current_context(EGLDisplay display, std::string& failure) {
  EGLint major = 0, minor = 0;
  if (egl().initialize(display, &major, &minor) != EGL_TRUE) {
    failure = "eglInitialize failed (" + egl_error_name(egl().get_error()) + ")";
    return EGL_NO_CONTEXT;
  }
  const auto fail = [&](const std::string& why) {
    failure = why;
    egl().terminate(display);
    return EGL_NO_CONTEXT;
  };
  if (!has_extension(egl().query_string(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
    return fail("EGL_KHR_surfaceless_context is not offered");
  }
  // No surface type is required: drawing goes to a framebuffer object.
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0,
                                      EGL_NONE};
  EGLConfig config = nullptr;
  EGLint config_count = 0;
  if (egl().choose_config(display, config_attributes, &config, 1, &config_count) != EGL_TRUE ||
      config_count < 1) {
    return fail("eglChooseConfig found no desktop OpenGL config");
  }
  if (egl().bind_api(EGL_OPENGL_API) != EGL_TRUE) {
    return fail("eglBindAPI(EGL_OPENGL_API) failed (" + egl_error_name(egl().get_error()) + ")");
  }
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       3,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  const EGLContext context =
      egl().create_context(display, config, EGL_NO_CONTEXT, context_attributes);
  if (context == EGL_NO_CONTEXT) {
    return fail("eglCreateContext(OpenGL 3.3 core) failed (" + egl_error_name(egl().get_error()) +
                ")");
  }
  if (egl().make_current(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) != EGL_TRUE) {
    const std::string error = egl_error_name(egl().get_error());
    egl().destroy_context(display, context);
    return fail("eglMakeCurrent without a surface failed (" + error + ")");
  }
  return context;
}

}  // namespace

EglContext::EglContext() {
  const char* only = std::getenv("WOBBLE_EGL_PLATFORM");
  const std::string forced = only == nullptr ? "" : only;
  if (!forced.empty() && forced != "device" && forced != "surfaceless") {
    // A setting the user gave, not a failure of the machine: bad input, exit 2.
    throw InputError("WOBBLE_EGL_PLATFORM: expected 'device' or 'surfaceless' (or unset), got '" +
                     forced + "'");
  }
  if (!egl().missing.empty()) {
    throw ContextError("cannot create a headless OpenGL 3.3 context: " + egl().missing);
  }
  const char* client_extensions = egl().query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  std::string failures;
  for (const std::string platform : {"device", "surfaceless"}) {
    if (!forced.empty() && forced != platform) continue;
    std::string failure;
    const EGLDisplay display = platform == "device"
                                   ? device_display(client_extensions, failure)
                                   : surfaceless_display(client_extensions, failure);
    EGLContext context = EGL_NO_CONTEXT;
    if (display != EGL_NO_DISPLAY) context = make_current_context(display, failure);
    if (context != EGL_NO_CONTEXT) {
      if (gladLoadGL(reinterpret_cast<GLADloadfunc>(egl().get_proc_address)) == 0) {
        egl().make_current(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        egl().destroy_context(display, context);
        egl().terminate(display);
        failure = "gladLoadGL could not load OpenGL 3.3 through eglGetProcAddress";
      } else {
        display_ = display;
        context_ = context;
        const auto text = [](GLenum name) {
          const auto* value = reinterpret_cast<const char*>(glGetString(name));
          return std::string(value == nullptr ? "?" : value);
        };
        driver_ = GlDriver{platform, text(GL_VENDOR), text(GL_RENDERER), text(GL_VERSION)};
        description_ = "EGL " + platform + ", " + driver_.vendor + ", " + driver_.renderer + ", " +
                       driver_.version;
        return;
      }
    }
    failures += (failures.empty() ? "" : "; ") + platform + ": " + failure;
  }
  throw ContextError("cannot create a headless OpenGL 3.3 context with EGL (" + failures +
                     "); install libegl-mesa0 and libgl1-mesa-dri for Mesa's software renderer, "
                     "or your GPU's EGL driver");
}

EglContext::~EglContext() {
  egl().make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  egl().destroy_context(display_, context_);
  egl().terminate(display_);
}

}  // namespace wobble
