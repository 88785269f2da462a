/* The OpenGL ES 2.0 entry points lixel uses, resolved at run time through the
 * platform's get-proc-address. Linking libGLESv2 next to libOSMesa would route calls
 * to no-op stubs, and one binary serves both platforms, so no gl* symbol is linked:
 * every call goes through lx_gl. Only ES 2.0 core functions are listed. */
#ifndef LX_GL_API_H
#define LX_GL_API_H
#define GL_GLES_PROTOTYPES 0
#include <GLES2/gl2.h>
#include <stdbool.h>

#define LX_GL_FUNCTIONS(X)                                                                   \
	X(void, ActiveTexture, (GLenum))                                                     \
	X(void, AttachShader, (GLuint, GLuint))                                              \
	X(void, BindAttribLocation, (GLuint, GLuint, const GLchar *))                        \
	X(void, BindBuffer, (GLenum, GLuint))                                                \
	X(void, BindFramebuffer, (GLenum, GLuint))                                           \
	X(void, BindRenderbuffer, (GLenum, GLuint))                                          \
	X(void, BindTexture, (GLenum, GLuint))                                               \
	X(void, BlendFunc, (GLenum, GLenum))                                                 \
	X(void, BufferData, (GLenum, GLsizeiptr, const void *, GLenum))                      \
	X(GLenum, CheckFramebufferStatus, (GLenum))                                          \
	X(void, Clear, (GLbitfield))                                                         \
	X(void, ClearColor, (GLfloat, GLfloat, GLfloat, GLfloat))                            \
	X(void, CompileShader, (GLuint))                                                     \
	X(GLuint, CreateProgram, (void))                                                     \
	X(GLuint, CreateShader, (GLenum))                                                    \
	X(void, CullFace, (GLenum))                                                          \
	X(void, DepthFunc, (GLenum))                                                         \
	X(void, DepthMask, (GLboolean))                                                      \
	X(void, DepthRangef, (GLfloat, GLfloat))                                             \
	X(void, DeleteBuffers, (GLsizei, const GLuint *))                                    \
	X(void, DeleteFramebuffers, (GLsizei, const GLuint *))                               \
	X(void, DeleteProgram, (GLuint))                                                     \
	X(void, DeleteRenderbuffers, (GLsizei, const GLuint *))                              \
	X(void, DeleteShader, (GLuint))                                                      \
	X(void, DeleteTextures, (GLsizei, const GLuint *))                                   \
	X(void, Disable, (GLenum))                                                           \
	X(void, DisableVertexAttribArray, (GLuint))                                          \
	X(void, DrawArrays, (GLenum, GLint, GLsizei))                                        \
	X(void, DrawElements, (GLenum, GLsizei, GLenum, const void *))                      \
	X(void, Enable, (GLenum))                                                            \
	X(void, EnableVertexAttribArray, (GLuint))                                           \
	X(void, Finish, (void))                                                              \
	X(void, Flush, (void))                                                               \
	X(void, FramebufferRenderbuffer, (GLenum, GLenum, GLenum, GLuint))                   \
	X(void, FramebufferTexture2D, (GLenum, GLenum, GLenum, GLuint, GLint))               \
	X(void, GenBuffers, (GLsizei, GLuint *))                                             \
	X(void, GenFramebuffers, (GLsizei, GLuint *))                                        \
	X(void, GenRenderbuffers, (GLsizei, GLuint *))                                       \
	X(void, GenTextures, (GLsizei, GLuint *))                                            \
	X(GLenum, GetError, (void))                                                          \
	X(void, GetFramebufferAttachmentParameteriv, (GLenum, GLenum, GLenum, GLint *))      \
	X(void, GetIntegerv, (GLenum, GLint *))                                              \
	X(void, GetProgramInfoLog, (GLuint, GLsizei, GLsizei *, GLchar *))                   \
	X(void, GetProgramiv, (GLuint, GLenum, GLint *))                                     \
	X(void, GetShaderInfoLog, (GLuint, GLsizei, GLsizei *, GLchar *))                    \
	X(void, GetShaderPrecisionFormat, (GLenum, GLenum, GLint *, GLint *))                \
	X(void, GetShaderiv, (GLuint, GLenum, GLint *))                                      \
	X(const GLubyte *, GetString, (GLenum))                                              \
	X(GLint, GetUniformLocation, (GLuint, const GLchar *))                               \
	X(void, LinkProgram, (GLuint))                                                       \
	X(void, PixelStorei, (GLenum, GLint))                                                \
	X(void, PolygonOffset, (GLfloat, GLfloat))                                           \
	X(void, ReadPixels, (GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void *))        \
	X(void, RenderbufferStorage, (GLenum, GLenum, GLsizei, GLsizei))                     \
	X(void, Scissor, (GLint, GLint, GLsizei, GLsizei))                                   \
	X(void, ShaderSource, (GLuint, GLsizei, const GLchar *const *, const GLint *))        \
	X(void, TexImage2D, (GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum, const void *)) \
	X(void, TexParameteri, (GLenum, GLenum, GLint))                                      \
	X(void, Uniform1f, (GLint, GLfloat))                                                 \
	X(void, Uniform1i, (GLint, GLint))                                                   \
	X(void, Uniform2f, (GLint, GLfloat, GLfloat))                                        \
	X(void, Uniform3f, (GLint, GLfloat, GLfloat, GLfloat))                               \
	X(void, Uniform3fv, (GLint, GLsizei, const GLfloat *))                               \
	X(void, Uniform4f, (GLint, GLfloat, GLfloat, GLfloat, GLfloat))                      \
	X(void, Uniform4fv, (GLint, GLsizei, const GLfloat *))                               \
	X(void, UniformMatrix4fv, (GLint, GLsizei, GLboolean, const GLfloat *))              \
	X(void, UseProgram, (GLuint))                                                        \
	X(void, VertexAttribPointer, (GLuint, GLint, GLenum, GLboolean, GLsizei, const void *)) \
	X(void, Viewport, (GLint, GLint, GLsizei, GLsizei))

struct lx_gl_api {
#define X(ret, name, args) ret(GL_APIENTRY *name) args;
	LX_GL_FUNCTIONS(X)
#undef X
};

extern struct lx_gl_api lx_gl;

/* Fills lx_gl for the context just made current; false with the first missing name in
 * *missing. */
bool lx_gl_load(void *(*get_proc)(const char *name), const char **missing);
/* Counts the contexts lx_gl_load has served: what a GL object name belongs to. */
unsigned lx_gl_context_serial(void);

#endif
