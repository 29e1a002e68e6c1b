// An OpenGL ES 3 context with no window, for the cameras (the way Gazebo renders them: OpenGL, here
// without a display): EGL's device enumeration (EGL_EXT_device_enumeration) finds a GPU with an EGL
// driver, else Mesa's llvmpipe (EGL_MESA_device_software), and the context renders into off-screen
// framebuffers only (surfaceless, EGL_KHR_surfaceless_context). Which device runs can be forced with
// TIANRACER_GL_DEVICE=cpu or gpu; the renderer's own name (GL_RENDERER) says which one did.
#pragma once

#include <memory>
#include <string>

namespace bullet_plant
{
enum class GlDevice { Any, Cpu, Gpu };

// TIANRACER_GL_DEVICE: "cpu", "gpu", or unset / "" for any (a GPU first); anything else is an
// error naming the value.
GlDevice glDeviceFromEnvironment(std::string& error);

class GlContext
{
public:
  // The context on the first device of the kind asked for (Any: a GPU first, then a software
  // one); null, with `why_not` saying what is missing (no EGL, no device, no ES 3 config), when
  // none can be made.
  static std::unique_ptr<GlContext> create(GlDevice device, std::string& why_not);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Makes it current on the calling thread (a context is current on one thread at a time).
  void makeCurrent() const;
  void release() const;
  // GL_RENDERER and GL_VERSION, read when it was made: "llvmpipe (LLVM 15.0.6, 256 bits)", ...
  const std::string& renderer() const { return renderer_; }
  const std::string& version() const { return version_; }
  bool software() const { return software_; }

private:
  GlContext() = default;
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  std::string renderer_, version_;
  bool software_ = false;
};

}  // namespace bullet_plant
