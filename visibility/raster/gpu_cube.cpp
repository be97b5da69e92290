// The GPU cube renderer (gpu_cube.h): one draw per view into an ID texture array, one compute
// pass per batch that ORs the seen faces' bits.
#include "visibility/raster/gpu_cube.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <tuple>
#include <utility>

namespace pvs {

namespace {

// A vertex: its position, its triangle's face, and which of the triangle's edges lie on the
// face's outline (bit k: corner k to corner k + 1; a diagonal inside a face is not), the same for
// the three corners.
struct GpuVertex {
    float x, y, z;
    uint32_t face;
    uint32_t outline;
};

// How near a pixel centre may lie to a face's outline, in pixels, and still count. A GPU snaps
// vertices to a sub-pixel grid (1/256 of a pixel on llvmpipe), so a centre on a snapped edge is a
// tie its fill rule settles; the CPU decides it exactly. Where faces meet along a seam, the face
// on the far side of the seam - a wall going on above a ceiling, seen from under it - is visible
// along the seam alone, a line no exact sample meets, yet a tied edge hands it whole rows of
// pixels: most of the regions the GPU saw and the CPU did not (every 14th region of e1m1, 4
// points, 64^2: 27 such bits of 7 448 without the margin, 5 with it). Those pixels still take
// their depth (they hide what is behind), but their face is not counted. A wider margin loses
// faces the CPU sees in slits (at 1/128 of a pixel, 26 bits the CPU alone saw).
constexpr float kOutlineMargin = 1.0f / 1024.0f;

// View k looks along axis k / 2 (sign + for even k); x and y are the next two axes in cyclic
// order, as in cube_raster.cpp. Clip z is the near distance, so depth = near / w (reversed: the
// nearest fragment has the largest depth) and the clip rule z <= w is the near plane.
constexpr const char* kVertexShader = R"(#version 450 core
layout(location = 0) in vec3 position;
layout(location = 1) in uint face;
layout(location = 2) in uint outline;
uniform vec3 eye;
uniform int view;
uniform float near_distance;
flat out uint face_id;
flat out uint face_outline;
noperspective out vec3 corner_weight; // barycentric on the picture: 0 on the edge facing a corner
void main()
{
    vec3 d = position - eye;
    int a = view >> 1;
    float w = (view & 1) != 0 ? -d[a] : d[a];
    gl_Position = vec4(d[(a + 1) % 3], d[(a + 2) % 3], near_distance, w);
    face_id = face;
    face_outline = outline;
    corner_weight = vec3(0.0);
    corner_weight[gl_VertexID % 3] = 1.0;
}
)";

// Whether the fragment's pixel centre lies within the margin of its face's outline: the weight
// of corner k falls to 0 on the edge from corner k + 1 to k + 2, at a rate per pixel its
// gradient gives.
constexpr const char* kOutlineFunction = R"(
flat in uint face_id;
flat in uint face_outline;
noperspective in vec3 corner_weight;
uniform float outline_margin;
bool near_outline()
{
    for (int k = 0; k < 3; ++k) {
        if ((face_outline & (1u << uint((k + 1) % 3))) == 0u)
            continue;
        float per_pixel = length(vec2(dFdx(corner_weight[k]), dFdy(corner_weight[k])));
        if (corner_weight[k] < outline_margin * per_pixel)
            return true;
    }
    return false;
}
)";

// The id's top bit marks a pixel whose face does not count (kOutlineMargin).
constexpr const char* kOpaqueFragmentShader = R"(
layout(location = 0) out uint id;
void main() { id = (face_id + 1u) | (near_outline() ? 0x80000000u : 0u); }
)";

// Early tests: only fragments in front of every opaque one reach the OR.
constexpr const char* kTranslucentFragmentShader = R"(
layout(early_fragment_tests) in;
layout(std430, binding = 0) buffer Bits { uint bits[]; };
void main()
{
    if (!near_outline())
        atomicOr(bits[face_id >> 5], 1u << (face_id & 31u));
}
)";

constexpr const char* kReduceShader = R"(#version 450 core
layout(local_size_x = 8, local_size_y = 8) in;
layout(r32ui, binding = 0) readonly uniform uimage2DArray ids;
layout(std430, binding = 0) buffer Bits { uint bits[]; };
void main()
{
    uint id = imageLoad(ids, ivec3(gl_GlobalInvocationID)).r;
    if (id != 0u && (id & 0x80000000u) == 0u) {
        uint f = id - 1u;
        atomicOr(bits[f >> 5], 1u << (f & 31u));
    }
}
)";

// Throws when `ok` is false, with the driver's log (get_log(object, size, length, text)), after
// deleting the object.
template <class GetLog, class Delete>
void check_built(GLint ok, GLuint object, GetLog get_log, Delete remove, const char* what)
{
    if (ok)
        return;
    char log[1024] = {};
    get_log(object, sizeof log, nullptr, log);
    remove(object);
    throw GlUnavailable(std::string("the GPU driver cannot ") + what + " the raster baker's shaders: " + log);
}

uint32_t compile(const GlApi& gl, GLenum stage, const char* source)
{
    const GLuint shader = gl.glCreateShader(stage);
    gl.glShaderSource(shader, 1, &source, nullptr);
    gl.glCompileShader(shader);
    GLint ok = 0;
    gl.glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    check_built(ok, shader, gl.glGetShaderInfoLog, gl.glDeleteShader, "compile");
    return shader;
}

uint32_t link(const GlApi& gl, std::initializer_list<std::pair<GLenum, const char*>> stages)
{
    const GLuint program = gl.glCreateProgram();
    std::vector<GLuint> shaders;
    for (const auto& [stage, source] : stages) {
        shaders.push_back(compile(gl, stage, source));
        gl.glAttachShader(program, shaders.back());
    }
    gl.glLinkProgram(program);
    for (GLuint s : shaders)
        gl.glDeleteShader(s);
    GLint ok = 0;
    gl.glGetProgramiv(program, GL_LINK_STATUS, &ok);
    check_built(ok, program, gl.glGetProgramInfoLog, gl.glDeleteProgram, "link");
    return program;
}

// Which edges of a face's triangles lie on its outline (gpu_vertex outline bits): an edge another
// triangle of the face also has, the other way round, is a diagonal inside it. `corners` holds
// the face's triangles, three corners each.
void outline_bits(const std::vector<glm::vec3>& corners, std::vector<uint32_t>& bits)
{
    const size_t triangles = corners.size() / 3;
    bits.assign(triangles, 0);
    for (size_t t = 0; t < triangles; ++t)
        for (uint32_t k = 0; k < 3; ++k) {
            const glm::vec3& a = corners[3 * t + k];
            const glm::vec3& b = corners[3 * t + (k + 1) % 3];
            bool inside = false;
            for (size_t u = 0; u < triangles && !inside; ++u)
                for (uint32_t m = 0; m < 3 && u != t && !inside; ++m)
                    inside = corners[3 * u + m] == b && corners[3 * u + (m + 1) % 3] == a;
            if (!inside)
                bits[t] |= 1u << k;
        }
}

// The zone's triangles as vertices, opaque faces first; returns the number of opaque vertices.
size_t zone_vertices(const Zone& zone, std::vector<GpuVertex>& out)
{
    const Mesh& mesh = zone.mesh;
    const std::vector<uint8_t> translucent = translucent_face_mask(zone);
    std::vector<glm::vec3> corners;
    std::vector<uint32_t> outline;
    const auto add_face = [&](uint32_t f) {
        const Face& face = mesh.faces[f];
        corners.clear();
        for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t) {
            if (3 * size_t(t) + 2 >= mesh.indices.size())
                break;
            const uint32_t i[3] = {mesh.indices[3 * size_t(t)], mesh.indices[3 * size_t(t) + 1],
                                   mesh.indices[3 * size_t(t) + 2]};
            if (i[0] >= mesh.positions.size() || i[1] >= mesh.positions.size() || i[2] >= mesh.positions.size())
                continue;
            for (uint32_t k : i)
                corners.push_back(mesh.positions[k]);
        }
        // A face of many triangles (a terrain sheet) is taken as all outline: quadratic otherwise.
        if (corners.size() <= 3 * 64)
            outline_bits(corners, outline);
        else
            outline.assign(corners.size() / 3, 7u);
        for (size_t k = 0; k < corners.size(); ++k)
            out.push_back({corners[k].x, corners[k].y, corners[k].z, f, outline[k / 3]});
    };
    const auto is_translucent = [&](uint32_t f) { return !translucent.empty() && translucent[f] != 0; };
    for (uint32_t f = 0; f < mesh.faces.size(); ++f)
        if (!is_translucent(f))
            add_face(f);
    const size_t opaque = out.size();
    for (uint32_t f = 0; f < mesh.faces.size(); ++f)
        if (is_translucent(f))
            add_face(f);
    return opaque;
}

void check_errors(const GlApi& gl, const char* what, uint32_t layers, uint32_t resolution)
{
    GLenum error = gl.glGetError();
    if (error == GL_NO_ERROR)
        return;
    while (gl.glGetError() != GL_NO_ERROR) {
    }
    if (error == GL_OUT_OF_MEMORY)
        throw GlUnavailable(std::string("the GPU is out of memory ") + what + " (" + std::to_string(layers) +
                            " views of " + std::to_string(resolution) +
                            "^2 a batch): bake with a smaller "
                            "--gpu-batch, or with --device cpu");
    throw GlUnavailable(std::string("OpenGL error 0x") + [&] {
        char hex[16];
        std::snprintf(hex, sizeof hex, "%04x", error);
        return std::string(hex);
    }() + " " + what);
}

} // namespace

GpuCube::GpuCube(GlHeadless& context, const Zone& zone, const CubeRasterOptions& options, uint32_t batch_views)
    : gl_(context.gl()), resolution_(std::max(options.resolution, 1u)),
      near_(options.near_distance > 0.0f ? options.near_distance : 0.05f), cull_back_faces_(options.cull_back_faces),
      faces_(uint32_t(zone.mesh.faces.size()))
{
    upload_mesh(zone);
    make_targets(batch_views);
    make_programs();
    // Fixed state: reversed depth in [0, 1], the picture's pixels, back faces by winding.
    const GlApi& gl = gl_;
    gl.glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    gl.glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    gl.glViewport(0, 0, GLsizei(resolution_), GLsizei(resolution_));
    gl.glEnable(GL_DEPTH_TEST);
    gl.glDepthFunc(GL_GREATER);
    if (cull_back_faces_) {
        gl.glEnable(GL_CULL_FACE);
        gl.glCullFace(GL_BACK);
    }
    gl.glBindVertexArray(vertex_array_);
    gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, bits_buffer_);
    check_errors(gl, "setting up the raster baker", batch_views_, resolution_);
}

// The zone's triangles in a vertex buffer (position, face, outline bits), and the face bits.
void GpuCube::upload_mesh(const Zone& zone)
{
    const GlApi& gl = gl_;
    std::vector<GpuVertex> vertices;
    opaque_vertices_ = int32_t(zone_vertices(zone, vertices));
    translucent_vertices_ = int32_t(vertices.size()) - opaque_vertices_;
    gl.glCreateBuffers(1, &vertex_buffer_);
    gl.glNamedBufferStorage(vertex_buffer_, GLsizeiptr(std::max<size_t>(vertices.size(), 1) * sizeof(GpuVertex)),
                            vertices.empty() ? nullptr : vertices.data(), 0);
    gl.glCreateVertexArrays(1, &vertex_array_);
    gl.glVertexArrayVertexBuffer(vertex_array_, 0, vertex_buffer_, 0, sizeof(GpuVertex));
    gl.glVertexArrayAttribFormat(vertex_array_, 0, 3, GL_FLOAT, GL_FALSE, 0);
    gl.glVertexArrayAttribIFormat(vertex_array_, 1, 1, GL_UNSIGNED_INT, 12);
    gl.glVertexArrayAttribIFormat(vertex_array_, 2, 1, GL_UNSIGNED_INT, 16);
    for (GLuint a : {0u, 1u, 2u}) {
        gl.glVertexArrayAttribBinding(vertex_array_, a, 0);
        gl.glEnableVertexArrayAttrib(vertex_array_, a);
    }
    bits_.resize(std::max<size_t>((faces_ + 31) / 32, 1));
    gl.glCreateBuffers(1, &bits_buffer_);
    gl.glNamedBufferStorage(bits_buffer_, GLsizeiptr(bits_.size() * 4), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

// The ID layers of a batch, the depth buffer and the framebuffer. The batch: `requested` views,
// else as many as fit in 256 MiB of IDs (at most 64 points' six), halved while the GPU is out
// of memory, down to one point's six.
void GpuCube::make_targets(uint32_t requested)
{
    const GlApi& gl = gl_;
    GLint max_layers = 0;
    gl.glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
    const uint64_t view_bytes = uint64_t(resolution_) * resolution_ * 4;
    const uint64_t fit = std::max<uint64_t>(1, (uint64_t(256) << 20) / view_bytes);
    batch_views_ = uint32_t(std::min<uint64_t>(
        {requested ? requested : std::min<uint64_t>(fit, 6 * 64), uint64_t(std::max(max_layers, 1))}));
    for (;;) {
        gl.glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &ids_);
        gl.glTextureStorage3D(ids_, 1, GL_R32UI, GLsizei(resolution_), GLsizei(resolution_), GLsizei(batch_views_));
        if (requested != 0 || batch_views_ <= 6)
            break;
        const GLenum error = gl.glGetError();
        if (error != GL_OUT_OF_MEMORY) {
            if (error != GL_NO_ERROR)
                throw GlUnavailable("the GPU driver cannot make the raster baker's ID buffer (OpenGL error " +
                                    std::to_string(error) + ")");
            break;
        }
        gl.glDeleteTextures(1, &ids_);
        batch_views_ /= 2;
    }
    gl.glCreateTextures(GL_TEXTURE_2D, 1, &depth_);
    gl.glTextureStorage2D(depth_, 1, GL_DEPTH_COMPONENT32F, GLsizei(resolution_), GLsizei(resolution_));
    check_errors(gl, "allocating the ID buffers", batch_views_, resolution_);
    gl.glCreateFramebuffers(1, &framebuffer_);
    gl.glNamedFramebufferTexture(framebuffer_, GL_DEPTH_ATTACHMENT, depth_, 0);
    gl.glNamedFramebufferTextureLayer(framebuffer_, GL_COLOR_ATTACHMENT0, ids_, 0, 0);
    if (gl.glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw GlUnavailable("the GPU driver cannot render into an R32UI texture array with a float depth buffer");
}

// The opaque and translucent drawing programs and the reduction, with their fixed uniforms.
void GpuCube::make_programs()
{
    const GlApi& gl = gl_;
    const std::string opaque = std::string("#version 450 core\n") + kOutlineFunction + kOpaqueFragmentShader;
    const std::string translucent =
        std::string("#version 450 core\n") + kOutlineFunction + kTranslucentFragmentShader;
    opaque_program_ = link(gl, {{GL_VERTEX_SHADER, kVertexShader}, {GL_FRAGMENT_SHADER, opaque.c_str()}});
    translucent_program_ = link(gl, {{GL_VERTEX_SHADER, kVertexShader}, {GL_FRAGMENT_SHADER, translucent.c_str()}});
    reduce_program_ = link(gl, {{GL_COMPUTE_SHADER, kReduceShader}});
    for (auto [program, eye, view] : {std::tuple{opaque_program_, &opaque_eye_, &opaque_view_},
                                      std::tuple{translucent_program_, &translucent_eye_, &translucent_view_}}) {
        *eye = gl.glGetUniformLocation(program, "eye");
        *view = gl.glGetUniformLocation(program, "view");
        gl.glProgramUniform1f(program, gl.glGetUniformLocation(program, "near_distance"), near_);
        gl.glProgramUniform1f(program, gl.glGetUniformLocation(program, "outline_margin"), kOutlineMargin);
    }
}

GpuCube::~GpuCube()
{
    const GlApi& gl = gl_;
    gl.glDeleteProgram(opaque_program_);
    gl.glDeleteProgram(translucent_program_);
    gl.glDeleteProgram(reduce_program_);
    gl.glDeleteFramebuffers(1, &framebuffer_);
    gl.glDeleteTextures(1, &ids_);
    gl.glDeleteTextures(1, &depth_);
    gl.glDeleteVertexArrays(1, &vertex_array_);
    gl.glDeleteBuffers(1, &vertex_buffer_);
    gl.glDeleteBuffers(1, &bits_buffer_);
}

// One view into ID layer `layer`: the opaque faces with depth, then the translucent ones.
void GpuCube::draw_view(const glm::vec3& eye, int view, uint32_t layer)
{
    const GlApi& gl = gl_;
    gl.glNamedFramebufferTextureLayer(framebuffer_, GL_COLOR_ATTACHMENT0, ids_, 0, GLint(layer));
    const float far_depth = 0.0f;
    gl.glClearNamedFramebufferfv(framebuffer_, GL_DEPTH, 0, &far_depth);
    // The view's axes (x, y, depth) are right-handed for the + views and left-handed for the -
    // ones, so a front face (its vertices anticlockwise from the eye) winds clockwise on the +
    // views' pictures and anticlockwise on the - views'.
    gl.glFrontFace(view % 2 == 0 ? GL_CW : GL_CCW);
    if (opaque_vertices_ > 0) {
        gl.glUseProgram(opaque_program_);
        gl.glProgramUniform3f(opaque_program_, opaque_eye_, eye.x, eye.y, eye.z);
        gl.glProgramUniform1i(opaque_program_, opaque_view_, view);
        gl.glDrawArrays(GL_TRIANGLES, 0, opaque_vertices_);
    }
    if (translucent_vertices_ > 0) {
        gl.glUseProgram(translucent_program_);
        gl.glProgramUniform3f(translucent_program_, translucent_eye_, eye.x, eye.y, eye.z);
        gl.glProgramUniform1i(translucent_program_, translucent_view_, view);
        gl.glDepthMask(GL_FALSE);
        gl.glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        gl.glDrawArrays(GL_TRIANGLES, opaque_vertices_, translucent_vertices_);
        // Back to writing both: the next view's depth clear obeys the depth mask.
        gl.glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        gl.glDepthMask(GL_TRUE);
    }
}

// ORs the face bits of the first `layers` ID layers into the bits buffer.
void GpuCube::reduce(uint32_t layers)
{
    const GlApi& gl = gl_;
    gl.glMemoryBarrier(GL_ALL_BARRIER_BITS);
    gl.glUseProgram(reduce_program_);
    gl.glBindImageTexture(0, ids_, 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI);
    const GLuint groups = (resolution_ + 7) / 8;
    gl.glDispatchCompute(groups, groups, layers);
    gl.glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

std::vector<uint32_t> GpuCube::view_ids(const glm::vec3& eye, int view)
{
    const GlApi& gl = gl_;
    const uint32_t zero = 0;
    gl.glClearTexImage(ids_, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    draw_view(eye, view, 0);
    std::vector<uint32_t> ids(size_t(resolution_) * resolution_);
    gl.glGetTextureSubImage(ids_, 0, 0, 0, 0, GLsizei(resolution_), GLsizei(resolution_), 1, GL_RED_INTEGER,
                            GL_UNSIGNED_INT, GLsizei(ids.size() * 4), ids.data());
    check_errors(gl, "reading a view back", batch_views_, resolution_);
    return ids;
}

void GpuCube::render(std::span<const glm::vec3> eyes, std::vector<uint8_t>& seen)
{
    if (eyes.empty())
        return;
    const GlApi& gl = gl_;
    const uint32_t zero = 0;
    gl.glClearNamedBufferData(bits_buffer_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    uint32_t layer = 0;
    for (const glm::vec3& eye : eyes)
        for (int view = 0; view < 6; ++view) {
            if (layer == 0)
                gl.glClearTexImage(ids_, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
            draw_view(eye, view, layer);
            if (++layer == batch_views_) {
                reduce(layer);
                layer = 0;
            }
        }
    if (layer > 0)
        reduce(layer);
    gl.glGetNamedBufferSubData(bits_buffer_, 0, GLsizeiptr(bits_.size() * 4), bits_.data());
    check_errors(gl, "rendering", batch_views_, resolution_);
    for (uint32_t f = 0; f < faces_ && f < seen.size(); ++f)
        if (bits_[f >> 5] >> (f & 31) & 1u)
            seen[f] = 1;
}

} // namespace pvs
