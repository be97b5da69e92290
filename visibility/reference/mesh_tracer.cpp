#include "visibility/reference/mesh_tracer.h"

#include "visibility/reference/embree_library.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>
#include <vector>

namespace pvs {

struct MeshTracer::Impl {
    const EmbreeApi& rtc = embree_api(); // throws when Embree cannot be opened
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<uint32_t> triangle_face;  // Embree primitive -> mesh face
    std::vector<glm::vec3> triangle_normal; // counter-clockwise front

    Hit intersect(RTCIntersectContext& context, const glm::vec3& origin, const glm::vec3& direction,
                  float t_far) const;

    ~Impl()
    {
        if (scene)
            rtc.rtcReleaseScene(scene);
        if (device)
            rtc.rtcReleaseDevice(device);
    }
};

MeshTracer::MeshTracer(const Zone& zone) : impl_(std::make_unique<Impl>())
{
    const Mesh& mesh = zone.mesh;
    std::vector<uint32_t> indices;
    for (uint32_t f = 0; f < mesh.faces.size(); ++f)
        for (uint32_t t = mesh.faces[f].first_triangle;
             t < mesh.faces[f].first_triangle + mesh.faces[f].triangle_count && 3 * size_t(t) + 2 < mesh.indices.size(); ++t) {
            const uint32_t* i = &mesh.indices[3 * size_t(t)];
            if (i[0] >= mesh.positions.size() || i[1] >= mesh.positions.size() || i[2] >= mesh.positions.size())
                continue;
            indices.insert(indices.end(), {i[0], i[1], i[2]});
            impl_->triangle_face.push_back(f);
            const glm::vec3& a = mesh.positions[i[0]];
            impl_->triangle_normal.push_back(glm::cross(mesh.positions[i[1]] - a, mesh.positions[i[2]] - a));
        }
    impl_->device = impl_->rtc.rtcNewDevice("threads=1"); // callers run their own threads
    if (!impl_->device)
        throw std::runtime_error("Embree: cannot create a device");
    impl_->scene = impl_->rtc.rtcNewScene(impl_->device);
    impl_->rtc.rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    impl_->rtc.rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
    if (!indices.empty() && !mesh.positions.empty()) {
        RTCGeometry geometry = impl_->rtc.rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        // Buffers Embree allocates itself carry the padding its vector loads need.
        auto* vertices = static_cast<float*>(impl_->rtc.rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.positions.size()));
        auto* triangles = static_cast<uint32_t*>(impl_->rtc.rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), indices.size() / 3));
        if (!vertices || !triangles)
            throw std::runtime_error("Embree: cannot allocate the mesh buffers");
        for (size_t v = 0; v < mesh.positions.size(); ++v)
            for (int k = 0; k < 3; ++k)
                vertices[3 * v + size_t(k)] = mesh.positions[v][k];
        std::copy(indices.begin(), indices.end(), triangles);
        impl_->rtc.rtcCommitGeometry(geometry);
        impl_->rtc.rtcAttachGeometry(impl_->scene, geometry);
        impl_->rtc.rtcReleaseGeometry(geometry);
    }
    impl_->rtc.rtcCommitScene(impl_->scene);
}

MeshTracer::~MeshTracer() = default;

size_t MeshTracer::triangle_count() const { return impl_->triangle_face.size(); }

namespace {

// Embree hands the filter the context it was given: ours carries the tracer's tables and the
// caller's filter after Embree's own fields.
struct FilterContext {
    RTCIntersectContext base;
    const std::vector<uint32_t>* triangle_face;
    const std::vector<glm::vec3>* triangle_normal;
    const MeshTracer::FaceFilter* filter;
};

void reject_filtered_hits(const RTCFilterFunctionNArguments* args)
{
    const auto* context = reinterpret_cast<const FilterContext*>(args->context);
    const MeshTracer::FaceFilter& filter = *context->filter;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0)
            continue;
        const unsigned primitive = RTCHitN_primID(args->hit, args->N, i);
        const uint32_t face = (*context->triangle_face)[primitive];
        bool keep = filter.face_enabled.empty() || (face < filter.face_enabled.size() && filter.face_enabled[face] != 0);
        if (keep && filter.front_only) {
            const glm::vec3 direction(RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                                      RTCRayN_dir_z(args->ray, args->N, i));
            keep = glm::dot((*context->triangle_normal)[primitive], direction) < 0.0f;
        }
        if (!keep)
            args->valid[i] = 0;
    }
}

FilterContext make_filter_context(const std::vector<uint32_t>& triangle_face,
                                  const std::vector<glm::vec3>& triangle_normal, const MeshTracer::FaceFilter& filter)
{
    FilterContext context{};
    rtcInitIntersectContext(&context.base);
    context.base.filter = reject_filtered_hits;
    context.triangle_face = &triangle_face;
    context.triangle_normal = &triangle_normal;
    context.filter = &filter;
    return context;
}

RTCRayHit make_ray(const glm::vec3& origin, const glm::vec3& direction, float t_far)
{
    RTCRayHit rh{};
    rh.ray.org_x = origin.x;
    rh.ray.org_y = origin.y;
    rh.ray.org_z = origin.z;
    rh.ray.dir_x = direction.x;
    rh.ray.dir_y = direction.y;
    rh.ray.dir_z = direction.z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = t_far;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

} // namespace

MeshTracer::Hit MeshTracer::Impl::intersect(RTCIntersectContext& context, const glm::vec3& origin,
                                            const glm::vec3& direction, float t_far) const
{
    RTCRayHit rh = make_ray(origin, direction, t_far);
    rtc.rtcIntersect1(scene, &context, &rh);
    Hit hit;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID || rh.hit.primID >= triangle_face.size())
        return hit;
    hit.hit = true;
    hit.face = triangle_face[rh.hit.primID];
    hit.t = rh.ray.tfar;
    hit.front = glm::dot(triangle_normal[rh.hit.primID], direction) < 0.0f;
    return hit;
}

MeshTracer::Hit MeshTracer::first_hit(const glm::vec3& origin, const glm::vec3& direction, float t_far) const
{
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    return impl_->intersect(context, origin, direction, t_far);
}

MeshTracer::Hit MeshTracer::first_hit(const glm::vec3& origin, const glm::vec3& direction, float t_far,
                                      const FaceFilter& filter) const
{
    FilterContext context = make_filter_context(impl_->triangle_face, impl_->triangle_normal, filter);
    return impl_->intersect(context.base, origin, direction, t_far);
}

void MeshTracer::first_hits(const glm::vec3& origin, std::span<const glm::vec3> directions, float t_near,
                            float t_far, std::span<Hit> out, const FaceFilter* filter) const
{
    constexpr size_t kPacket = 8;
    FilterContext filtered{};
    rtcInitIntersectContext(&filtered.base);
    if (filter)
        filtered = make_filter_context(impl_->triangle_face, impl_->triangle_normal, *filter);
    RTCIntersectContext& context = filtered.base;
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    for (size_t first = 0; first < directions.size(); first += kPacket) {
        const size_t count = std::min(kPacket, directions.size() - first);
        alignas(32) int valid[kPacket];
        alignas(32) RTCRayHit8 packet{};
        for (size_t i = 0; i < kPacket; ++i) {
            valid[i] = i < count ? -1 : 0;
            const glm::vec3& d = directions[first + std::min(i, count - 1)];
            packet.ray.org_x[i] = origin.x;
            packet.ray.org_y[i] = origin.y;
            packet.ray.org_z[i] = origin.z;
            packet.ray.dir_x[i] = d.x;
            packet.ray.dir_y[i] = d.y;
            packet.ray.dir_z[i] = d.z;
            packet.ray.tnear[i] = t_near;
            packet.ray.tfar[i] = t_far;
            packet.ray.mask[i] = 0xFFFFFFFFu;
            packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
            packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
        }
        impl_->rtc.rtcIntersect8(valid, impl_->scene, &context, &packet);
        for (size_t i = 0; i < count; ++i) {
            Hit& hit = out[first + i];
            hit = {};
            const unsigned primitive = packet.hit.primID[i];
            if (packet.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID || primitive >= impl_->triangle_face.size())
                continue;
            hit.hit = true;
            hit.face = impl_->triangle_face[primitive];
            hit.t = packet.ray.tfar[i];
            hit.front = glm::dot(impl_->triangle_normal[primitive], directions[first + i]) < 0.0f;
        }
    }
}

bool MeshTracer::occluded(const glm::vec3& origin, const glm::vec3& direction, float t_far,
                          const FaceFilter& filter) const
{
    FilterContext context = make_filter_context(impl_->triangle_face, impl_->triangle_normal, filter);
    RTCRay ray = make_ray(origin, direction, t_far).ray;
    impl_->rtc.rtcOccluded1(impl_->scene, &context.base, &ray);
    return ray.tfar < 0.0f; // Embree marks an occluded ray with tfar = -inf
}

bool MeshTracer::in_open_space(const glm::vec3& point, float clearance) const
{
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 d(0.0f);
            d[axis] = sign;
            const Hit h = first_hit(point, d, std::numeric_limits<float>::infinity());
            if (!h.hit || !h.front || !(h.t > clearance))
                return false;
        }
    return true;
}

} // namespace pvs
