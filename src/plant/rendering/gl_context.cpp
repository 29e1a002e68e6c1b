#include "rendering/gl_context.h"

#include <cstdlib>
#include <cstring>
#include <vector>

#define EGL_EGLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>

namespace bullet_plant
{
namespace
{
bool hasExtension(const char* extensions, const char* name)
{
  if (!extensions)
    return false;
  const size_t n = std::strlen(name);
  for (const char* p = std::strstr(extensions, name); p; p = std::strstr(p + n, name))
    if ((p == extensions || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
      return true;
  return false;
}

template <class F>
F eglFunction(const char* name)
{
  return reinterpret_cast<F>(eglGetProcAddress(name));
}

struct Device
{
  EGLDeviceEXT handle;
  bool software;
};

// Every EGL device, the hardware ones first (in EGL's order), then the software ones.
std::vector<Device> eglDevices(std::string& why_not)
{
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!hasExtension(client, "EGL_EXT_device_enumeration") || !hasExtension(client, "EGL_EXT_platform_device"))
  {
    why_not = "EGL has no device enumeration (EGL_EXT_device_enumeration, EGL_EXT_platform_device): install "
              "Mesa's EGL driver (libegl-mesa0) or a GPU's";
    return {};
  }
  auto query_devices = eglFunction<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  auto query_device_string = eglFunction<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  EGLint count = 0;
  if (!query_devices || !query_device_string || !query_devices(0, nullptr, &count) || count == 0)
  {
    why_not = "EGL lists no device (no GPU driver and no Mesa software driver: install libegl-mesa0 and "
              "libgl1-mesa-dri)";
    return {};
  }
  std::vector<EGLDeviceEXT> handles(static_cast<size_t>(count), EGL_NO_DEVICE_EXT);
  query_devices(count, handles.data(), &count);
  std::vector<Device> hardware, software;
  for (EGLint i = 0; i < count; ++i)
  {
    const bool is_software = hasExtension(query_device_string(handles[size_t(i)], EGL_EXTENSIONS),
                                          "EGL_MESA_device_software");
    (is_software ? software : hardware).push_back(Device{handles[size_t(i)], is_software});
  }
  hardware.insert(hardware.end(), software.begin(), software.end());
  return hardware;
}
}  // namespace

GlDevice glDeviceFromEnvironment(std::string& error)
{
  const char* value = std::getenv("TIANRACER_GL_DEVICE");
  const std::string v = value ? value : "";
  if (v.empty())
    return GlDevice::Any;
  if (v == "cpu")
    return GlDevice::Cpu;
  if (v == "gpu")
    return GlDevice::Gpu;
  error = "TIANRACER_GL_DEVICE is '" + v + "': it takes cpu (Mesa's llvmpipe), gpu, or nothing (a GPU if there is one)";
  return GlDevice::Any;
}

std::unique_ptr<GlContext> GlContext::create(GlDevice wanted, std::string& why_not)
{
  const std::vector<Device> devices = eglDevices(why_not);
  if (devices.empty())
    return nullptr;
  auto platform_display = eglFunction<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  std::string tried;
  for (const Device& device : devices)
  {
    if ((wanted == GlDevice::Cpu && !device.software) || (wanted == GlDevice::Gpu && device.software))
      continue;
    EGLDisplay display = platform_display(EGL_PLATFORM_DEVICE_EXT, device.handle, nullptr);
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor))
    {
      tried += " a device would not initialise;";
      continue;
    }
    if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
    {
      tried += " a device has no surfaceless contexts;";
      continue;
    }
    // No window and no pbuffer: any surface type (the default asks for windows, which a device lacks).
    const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE, EGL_DONT_CARE, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    eglBindAPI(EGL_OPENGL_ES_API);
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    EGLContext context = EGL_NO_CONTEXT;
    if (eglChooseConfig(display, config_attributes, &config, 1, &configs) && configs > 0)
      context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
    if (context == EGL_NO_CONTEXT)
    {
      tried += " a device offers no OpenGL ES 3 context;";
      continue;
    }
    std::unique_ptr<GlContext> gl(new GlContext());
    gl->display_ = display;
    gl->context_ = context;
    gl->software_ = device.software;
    gl->makeCurrent();
    gl->renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    gl->version_ = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    gl->release();
    return gl;
  }
  why_not = wanted == GlDevice::Any ? "no EGL device gave an OpenGL ES 3 context:" + tried
            : std::string("no ") + (wanted == GlDevice::Cpu ? "software (Mesa llvmpipe)" : "GPU") +
                  " EGL device" + (tried.empty() ? "" : " that works:" + tried) +
                  " (TIANRACER_GL_DEVICE asked for one)";
  return nullptr;
}

// The display stays initialised: EGL has one per device for the whole process, and terminating
// it would take the other contexts on it along.
GlContext::~GlContext()
{
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
}

void GlContext::makeCurrent() const { eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_); }

void GlContext::release() const { eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }

}  // namespace bullet_plant
