/// @file Mesa llvmpipe visibility peer (see peer_llvmpipe.hpp).
#include "bench/peer_llvmpipe.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#define GL_GLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include "core/stopwatch.hpp"

namespace silva::bench {

namespace {

/// Vertex shader: object space -> clip space; passes the uvs on (perspective-correct).
constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 uv;
uniform mat4 object_to_clip;
out vec2 v_uv;
void main() { v_uv = uv; gl_Position = object_to_clip * vec4(position, 1.0); }
)";

/// Fragment shader writing (instance, triangle); MASKED adds the alpha test.
constexpr const char* kFragmentShader = R"(
in vec2 v_uv;
uniform uint instance_index;
uniform uint first_triangle;
uniform sampler2D mask;
uniform float cutoff;
layout(location = 0) out uvec2 ids;
void main() {
#ifdef MASKED
  if (texture(mask, v_uv).r < cutoff) discard;
#endif
  ids = uvec2(instance_index, first_triangle + uint(gl_PrimitiveID));
}
)";

/// Throws with `what` and the EGL error.
[[noreturn]] void egl_fail(const std::string& what) {
  throw std::runtime_error("llvmpipe peer: " + what + " failed (EGL error 0x" + std::to_string(eglGetError()) + ")");
}

/// Compiles one shader stage from `sources`.
GLuint compile(GLenum stage, std::vector<const char*> sources) {
  const GLuint s = glCreateShader(stage);
  glShaderSource(s, GLsizei(sources.size()), sources.data(), nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("llvmpipe peer: shader compilation failed: ") + log);
  }
  return s;
}

/// Links the id program, with the alpha test when `masked`.
GLuint link_program(bool masked) {
  const GLuint vs = compile(GL_VERTEX_SHADER, {kVertexShader});
  const GLuint fs = compile(GL_FRAGMENT_SHADER, {"#version 330 core\n", masked ? "#define MASKED\n" : "", kFragmentShader});
  const GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  glLinkProgram(p);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) throw std::runtime_error("llvmpipe peer: program link failed");
  return p;
}

/// Uniform locations of one program.
struct Program {
  GLuint id = 0;                 ///< GL program.
  GLint object_to_clip = -1;     ///< mat4 uniform.
  GLint instance_index = -1;     ///< uint uniform.
  GLint first_triangle = -1;     ///< uint uniform.
  GLint cutoff = -1;             ///< float uniform (masked program only).
};

/// One uploaded mesh.
struct GpuMesh {
  GLuint vao = 0, vbo = 0, ibo = 0;  ///< Vertex array, interleaved position+uv buffer, index buffer.
};

/// Camera (OpenCV axes) -> clip: x, y to NDC so that window (x, y) = image (u, v) (row 0 first in
/// memory), reverse depth z_ndc = near / z with glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE).
Mat4d camera_to_clip(const Camera& c) {
  Mat4d p = Mat4d::Zero();
  p(0, 0) = 2.0 * c.fx / c.width;
  p(0, 2) = 2.0 * c.cx / c.width - 1.0;
  p(1, 1) = 2.0 * c.fy / c.height;
  p(1, 2) = 2.0 * c.cy / c.height - 1.0;
  p(2, 3) = c.near;
  p(3, 2) = 1.0;
  return p;
}

}  // namespace

struct LlvmpipePeer::Impl {
  PeerView view;
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  Program opaque, masked;
  std::vector<GpuMesh> meshes;
  std::vector<GLuint> textures;      // one per distinct mask
  std::vector<const AlphaMask*> texture_masks;
  GLuint fbo = 0, depth_rb = 0, id_rb = 0;
  std::vector<float> depth;          // read-back window depth (near / z)
  std::vector<uint32_t> ids;         // read-back (instance, triangle) pairs
  double setup_ms = 0;

  /// EGL surfaceless display + OpenGL 4.5 core context on llvmpipe.
  void create_context(int lp_threads) {
    setenv("GALLIUM_DRIVER", "llvmpipe", 1);
    setenv("LP_NUM_THREADS", std::to_string(lp_threads).c_str(), 1);
    display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) egl_fail("eglGetPlatformDisplay(surfaceless)");
    if (!eglInitialize(display, nullptr, nullptr)) egl_fail("eglInitialize");
    if (!eglBindAPI(EGL_OPENGL_API)) egl_fail("eglBindAPI");
    const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config;
    EGLint n = 0;
    if (!eglChooseConfig(display, config_attribs, &config, 1, &n) || n < 1) egl_fail("eglChooseConfig");
    const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
    if (context == EGL_NO_CONTEXT) egl_fail("eglCreateContext(OpenGL 4.5 core)");
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) egl_fail("eglMakeCurrent");
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (!renderer || std::string(renderer).find("llvmpipe") == std::string::npos)
      throw std::runtime_error(std::string("llvmpipe peer: the context runs on '") + (renderer ? renderer : "?") +
                               "', not llvmpipe");
  }

  /// Programs, mesh buffers, mask textures and the framebuffer.
  void upload() {
    for (bool m : {false, true}) {
      Program& p = m ? masked : opaque;
      p.id = link_program(m);
      p.object_to_clip = glGetUniformLocation(p.id, "object_to_clip");
      p.instance_index = glGetUniformLocation(p.id, "instance_index");
      p.first_triangle = glGetUniformLocation(p.id, "first_triangle");
      p.cutoff = glGetUniformLocation(p.id, "cutoff");
    }
    for (const render::MeshLods& lods : view.scene->meshes) {
      const Mesh& mesh = *lods.lods[0];
      std::vector<float> vertices;
      vertices.reserve(mesh.positions.size() * 5);
      for (size_t k = 0; k < mesh.positions.size(); ++k) {
        const Vec2f uv = mesh.uvs.empty() ? Vec2f(0, 0) : mesh.uvs[k];
        vertices.insert(vertices.end(), {mesh.positions[k].x(), mesh.positions[k].y(), mesh.positions[k].z(), uv.x(), uv.y()});
      }
      GpuMesh g;
      glGenVertexArrays(1, &g.vao);
      glBindVertexArray(g.vao);
      glGenBuffers(1, &g.vbo);
      glBindBuffer(GL_ARRAY_BUFFER, g.vbo);
      glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(), GL_STATIC_DRAW);
      glGenBuffers(1, &g.ibo);
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.ibo);
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(uint32_t)), mesh.indices.data(),
                   GL_STATIC_DRAW);
      glEnableVertexAttribArray(0);
      glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), nullptr);
      glEnableVertexAttribArray(1);
      glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float), reinterpret_cast<void*>(3 * sizeof(float)));
      meshes.push_back(g);
      for (const MeshPart& part : mesh.parts)
        if (part.mask && texture_index(part.mask.get()) < 0) upload_mask(*part.mask);
    }
    glBindVertexArray(0);
    const Camera& cam = *view.camera;
    glGenRenderbuffers(1, &depth_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, cam.width, cam.height);
    glGenRenderbuffers(1, &id_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, id_rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RG32UI, cam.width, cam.height);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, id_rb);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("llvmpipe peer: framebuffer incomplete");
    glViewport(0, 0, cam.width, cam.height);
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);  // reverse depth; equal depths keep the first draw (lower instance, triangle)
    glFrontFace(GL_CW);       // window y = image v (down), so counter-clockwise object faces turn clockwise
    glCullFace(GL_BACK);
    depth.resize(size_t(cam.width) * size_t(cam.height));
    ids.resize(2 * depth.size());
    glFinish();
    if (glGetError() != GL_NO_ERROR) throw std::runtime_error("llvmpipe peer: GL error during upload");
  }

  /// Index of the texture of `mask`, or -1.
  int texture_index(const AlphaMask* mask) const {
    for (size_t k = 0; k < texture_masks.size(); ++k)
      if (texture_masks[k] == mask) return int(k);
    return -1;
  }

  /// Uploads one mask as an R8 texture, nearest filtering, repeat wrap (AlphaMask::opaque).
  void upload_mask(const AlphaMask& mask) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, mask.width, mask.height, 0, GL_RED, GL_UNSIGNED_BYTE, mask.alpha.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    textures.push_back(t);
    texture_masks.push_back(&mask);
  }

  /// Draws every part of every instance, in instance order.
  void draw() {
    const Camera& cam = *view.camera;
    const GLuint no_hit[4] = {render::kNoInstance, 0, 0, 0};
    const float far_depth = float(cam.near / cam.far);
    glClearBufferuiv(GL_COLOR, 0, no_hit);
    glClearBufferfv(GL_DEPTH, 0, &far_depth);
    const Mat4d view_to_clip = camera_to_clip(cam) * cam.world_to_camera();
    const render::Scene& scene = *view.scene;
    for (size_t i = 0; i < scene.instances.size(); ++i) {
      const render::Instance& inst = scene.instances[i];
      const Mesh& mesh = *scene.meshes[inst.mesh].lods[0];
      Mat4d model = Mat4d::Identity();
      model.topRows<3>() = inst.object_to_world.cast<double>();
      const Eigen::Matrix4f m = (view_to_clip * model).cast<float>();
      glBindVertexArray(meshes[inst.mesh].vao);
      for (const MeshPart& part : mesh.parts) {
        const Program& p = part.mask ? masked : opaque;
        glUseProgram(p.id);
        glUniformMatrix4fv(p.object_to_clip, 1, GL_FALSE, m.data());
        glUniform1ui(p.instance_index, GLuint(i));
        glUniform1ui(p.first_triangle, part.first_index / 3);
        if (part.mask) {
          glBindTexture(GL_TEXTURE_2D, textures[size_t(texture_index(part.mask.get()))]);
          glUniform1f(p.cutoff, part.mask->cutoff);
        }
        if (part.double_sided) glDisable(GL_CULL_FACE);
        else glEnable(GL_CULL_FACE);
        glDrawElements(GL_TRIANGLES, GLsizei(part.index_count), GL_UNSIGNED_INT,
                       reinterpret_cast<void*>(size_t(part.first_index) * sizeof(uint32_t)));
      }
    }
  }
};

LlvmpipePeer::LlvmpipePeer(const PeerView& view, int lp_threads) : impl_(std::make_unique<Impl>()) {
  impl_->view = view;
  const Stopwatch clock;
  impl_->create_context(lp_threads);
  impl_->upload();
  impl_->setup_ms = 1000 * clock.seconds();
}

LlvmpipePeer::~LlvmpipePeer() {
  Impl& s = *impl_;
  if (s.context != EGL_NO_CONTEXT) {
    for (const GpuMesh& g : s.meshes) {
      glDeleteVertexArrays(1, &g.vao);
      glDeleteBuffers(1, &g.vbo);
      glDeleteBuffers(1, &g.ibo);
    }
    glDeleteTextures(GLsizei(s.textures.size()), s.textures.data());
    glDeleteFramebuffers(1, &s.fbo);
    glDeleteRenderbuffers(1, &s.depth_rb);
    glDeleteRenderbuffers(1, &s.id_rb);
    glDeleteProgram(s.opaque.id);
    glDeleteProgram(s.masked.id);
    eglMakeCurrent(s.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(s.display, s.context);
  }
  if (s.display != EGL_NO_DISPLAY) eglTerminate(s.display);
}

void LlvmpipePeer::render(bool readback) {
  Impl& s = *impl_;
  s.draw();
  if (readback) {
    const Camera& cam = *s.view.camera;
    glReadPixels(0, 0, cam.width, cam.height, GL_DEPTH_COMPONENT, GL_FLOAT, s.depth.data());
    glReadPixels(0, 0, cam.width, cam.height, GL_RG_INTEGER, GL_UNSIGNED_INT, s.ids.data());
  }
  glFinish();
}

PeerFrame LlvmpipePeer::frame() const {
  const Impl& s = *impl_;
  const Camera& cam = *s.view.camera;
  PeerFrame f;
  f.resize(cam.width, cam.height);
  for (size_t i = 0; i < s.depth.size(); ++i) {
    if (s.ids[2 * i] == render::kNoInstance) continue;
    f.depth[i] = float(cam.near / double(s.depth[i]));
    f.instance[i] = s.ids[2 * i];
    f.triangle[i] = s.ids[2 * i + 1];
  }
  return f;
}

double LlvmpipePeer::setup_ms() const { return impl_->setup_ms; }

}  // namespace silva::bench
