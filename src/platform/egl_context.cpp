#include "egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <glad/gl.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "sim/input_error.h"

namespace wobble {

namespace {

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
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  const auto platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
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
              egl_error_name(eglGetError()) + ")";
  }
  return display;
}

EGLDisplay surfaceless_display(const char* client_extensions, std::string& failure) {
  if (!has_extension(client_extensions, "EGL_MESA_platform_surfaceless")) {
    failure = "EGL_MESA_platform_surfaceless is not offered";
    return EGL_NO_DISPLAY;
  }
  const auto platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  const EGLDisplay display =
      platform_display == nullptr
          ? EGL_NO_DISPLAY
          : platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) {
    failure = "eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA) failed (" +
              egl_error_name(eglGetError()) + ")";
  }
  return display;
}

// Initialize `display` and make a GL 3.3 core context current on it without a surface.
EGLContext make_current_context(EGLDisplay display, std::string& failure) {
  EGLint major = 0, minor = 0;
  if (eglInitialize(display, &major, &minor) != EGL_TRUE) {
    failure = "eglInitialize failed (" + egl_error_name(eglGetError()) + ")";
    return EGL_NO_CONTEXT;
  }
  const auto fail = [&](const std::string& why) {
    failure = why;
    eglTerminate(display);
    return EGL_NO_CONTEXT;
  };
  if (!has_extension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
    return fail("EGL_KHR_surfaceless_context is not offered");
  }
  // No surface type is required: drawing goes to a framebuffer object.
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0,
                                      EGL_NONE};
  EGLConfig config = nullptr;
  EGLint config_count = 0;
  if (eglChooseConfig(display, config_attributes, &config, 1, &config_count) != EGL_TRUE ||
      config_count < 1) {
    return fail("eglChooseConfig found no desktop OpenGL config");
  }
  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) {
    return fail("eglBindAPI(EGL_OPENGL_API) failed (" + egl_error_name(eglGetError()) + ")");
  }
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       3,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  const EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
  if (context == EGL_NO_CONTEXT) {
    return fail("eglCreateContext(OpenGL 3.3 core) failed (" + egl_error_name(eglGetError()) + ")");
  }
  if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) != EGL_TRUE) {
    const std::string error = egl_error_name(eglGetError());
    eglDestroyContext(display, context);
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
  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
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
      if (gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)) == 0) {
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context);
        eglTerminate(display);
        failure = "gladLoadGL could not load OpenGL 3.3 through eglGetProcAddress";
      } else {
        display_ = display;
        context_ = context;
        description_ = "EGL " + platform + ", " +
                       reinterpret_cast<const char*>(glGetString(GL_RENDERER)) + ", " +
                       reinterpret_cast<const char*>(glGetString(GL_VERSION));
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
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

}  // namespace wobble
