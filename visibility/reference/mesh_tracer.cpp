#include "visibility/reference/mesh_tracer.h"

#include <embree3/rtcore.h>

#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>
#include <vector>

namespace pvs {

struct MeshTracer::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<uint32_t> triangle_face;  // Embree primitive -> mesh face
    std::vector<glm::vec3> triangle_normal; // counter-clockwise front

    ~Impl()
    {
        if (scene)
            rtcReleaseScene(scene);
        if (device)
            rtcReleaseDevice(device);
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
    impl_->device = rtcNewDevice("threads=1"); // callers run their own threads
    if (!impl_->device)
        throw std::runtime_error("Embree: cannot create a device");
    impl_->scene = rtcNewScene(impl_->device);
    rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
    if (!indices.empty() && !mesh.positions.empty()) {
        RTCGeometry geometry = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        // Buffers Embree allocates itself carry the padding its vector loads need.
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.positions.size()));
        auto* triangles = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), indices.size() / 3));
        if (!vertices || !triangles)
            throw std::runtime_error("Embree: cannot allocate the mesh buffers");
        for (size_t v = 0; v < mesh.positions.size(); ++v)
            for (int k = 0; k < 3; ++k)
                vertices[3 * v + size_t(k)] = mesh.positions[v][k];
        std::copy(indices.begin(), indices.end(), triangles);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(impl_->scene, geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(impl_->scene);
}

MeshTracer::~MeshTracer() = default;

size_t MeshTracer::triangle_count() const { return impl_->triangle_face.size(); }

MeshTracer::Hit MeshTracer::first_hit(const glm::vec3& origin, const glm::vec3& direction, float t_far) const
{
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
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
    rtcIntersect1(impl_->scene, &context, &rh);
    Hit hit;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID || rh.hit.primID >= impl_->triangle_face.size())
        return hit;
    hit.hit = true;
    hit.face = impl_->triangle_face[rh.hit.primID];
    hit.t = rh.ray.tfar;
    hit.front = glm::dot(impl_->triangle_normal[rh.hit.primID], direction) < 0.0f;
    return hit;
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
