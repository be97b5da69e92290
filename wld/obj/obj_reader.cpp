#include "wld/obj/obj_reader.h"

#include "visibility/file_error.h"
#include "wld/common/read_file.h"
#include "wld/eq/stb_image_io.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

namespace pvs {

namespace {

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// The first word after `keyword` on each line that starts with it ("mtllib", "usemtl").
std::vector<std::string> keyword_values(const std::string& text, const std::string& keyword)
{
    std::vector<std::string> values;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string first, value;
        if (words >> first && first == keyword && words >> value)
            values.push_back(value);
    }
    return values;
}

// The .mtl text beside the OBJ (empty when absent), plus "newmtl NAME" for every usemtl name it
// does not define, so that tinyobjloader gives those triangles a material id too.
std::string material_text(const std::string& obj_text, const std::filesystem::path& dir, std::string& mtl_file)
{
    std::string mtl;
    for (const std::string& name : keyword_values(obj_text, "mtllib")) {
        std::error_code ec;
        const std::filesystem::path p = dir / name;
        if (std::filesystem::is_regular_file(p, ec)) {
            const std::vector<uint8_t> bytes = read_whole_file(p.string());
            mtl.assign(bytes.begin(), bytes.end());
            mtl_file = p.string();
            break;
        }
    }
    const std::vector<std::string> defined = keyword_values(mtl, "newmtl");
    const std::set<std::string> known(defined.begin(), defined.end());
    std::set<std::string> added;
    for (const std::string& name : keyword_values(obj_text, "usemtl"))
        if (!known.count(name) && added.insert(name).second)
            mtl += "\nnewmtl " + name + "\n";
    return mtl;
}

Material make_material(const tinyobj::material_t& m, const std::filesystem::path& dir)
{
    Material material;
    material.name = m.name;
    if (m.diffuse_texname.empty())
        return material;
    std::error_code ec;
    const std::filesystem::path p = dir / m.diffuse_texname;
    if (!std::filesystem::is_regular_file(p, ec))
        return material;
    if (const auto image = decode_bmp(read_whole_file(p.string())))
        set_material_rgba(material, image->width, image->height, image->rgba);
    return material;
}

uint64_t object_line_offset(const std::string& text, const std::string& name)
{
    for (const char* keyword : {"\no ", "\ng "}) {
        const size_t at = text.find(keyword + name);
        if (at != std::string::npos)
            return at + 1;
    }
    return 0;
}

class ZoneBuilder {
public:
    ZoneBuilder(const tinyobj::attrib_t& attrib, const std::string& text, const std::string& path, Zone& zone)
        : attrib_(attrib), text_(text), path_(path), zone_(zone)
    {
    }

    void add_shape(const tinyobj::shape_t& shape, uint32_t default_material)
    {
        const tinyobj::mesh_t& mesh = shape.mesh;
        if (mesh.indices.size() != 3 * mesh.num_face_vertices.size())
            fail(shape, "a face that is not a triangle after triangulation");
        Region region;
        uint32_t current = UINT32_MAX;
        for (size_t t = 0; t < mesh.num_face_vertices.size(); ++t) {
            const int id = t < mesh.material_ids.size() ? mesh.material_ids[t] : -1;
            const uint32_t material = id >= 0 ? uint32_t(id) : default_material;
            if (material != current) {
                current = material;
                Face face;
                face.first_triangle = uint32_t(zone_.mesh.indices.size() / 3);
                face.material = material;
                zone_.region_faces.push_back(uint32_t(zone_.mesh.faces.size()));
                zone_.mesh.faces.push_back(face);
            }
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 p = vertex(shape, t, mesh.indices[3 * t + size_t(k)]);
                region.bounds.grow(p);
                zone_.mesh.indices.push_back(uint32_t(zone_.mesh.positions.size()));
                zone_.mesh.positions.push_back(p);
                zone_.mesh.uvs.push_back(uv(shape, t, mesh.indices[3 * t + size_t(k)]));
            }
            ++zone_.mesh.faces.back().triangle_count;
        }
        zone_.regions.push_back(region);
        zone_.region_names.push_back(shape.name);
        zone_.region_face_offsets.push_back(uint32_t(zone_.region_faces.size()));
    }

private:
    [[noreturn]] void fail(const tinyobj::shape_t& shape, const std::string& problem) const
    {
        throw FileError(path_, object_line_offset(text_, shape.name), "object '" + shape.name + "': " + problem);
    }

    glm::vec3 vertex(const tinyobj::shape_t& shape, size_t face, const tinyobj::index_t& index) const
    {
        if (index.vertex_index < 0 || 3 * size_t(index.vertex_index) + 2 >= attrib_.vertices.size())
            fail(shape, "face " + std::to_string(face + 1) + " uses vertex " + std::to_string(index.vertex_index + 1) +
                            " of " + std::to_string(attrib_.vertices.size() / 3));
        const float* v = &attrib_.vertices[3 * size_t(index.vertex_index)];
        const glm::vec3 p(v[0], -v[2], v[1]); // y-up file to z-up zone
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            fail(shape, "face " + std::to_string(face + 1) + " uses a vertex that is not a finite number");
        return p;
    }

    glm::vec2 uv(const tinyobj::shape_t& shape, size_t face, const tinyobj::index_t& index) const
    {
        if (index.texcoord_index < 0)
            return glm::vec2(0.0f);
        if (2 * size_t(index.texcoord_index) + 1 >= attrib_.texcoords.size())
            fail(shape, "face " + std::to_string(face + 1) + " uses texture coordinate " +
                            std::to_string(index.texcoord_index + 1) + " of " +
                            std::to_string(attrib_.texcoords.size() / 2));
        const float* t = &attrib_.texcoords[2 * size_t(index.texcoord_index)];
        return {t[0], 1.0f - t[1]};
    }

    const tinyobj::attrib_t& attrib_;
    const std::string& text_;
    const std::string& path_;
    Zone& zone_;
};

} // namespace

bool is_obj_path(const std::string& path) { return lower(std::filesystem::path(path).extension().string()) == ".obj"; }

Zone read_obj_zone(std::span<const uint8_t> bytes, const std::string& path)
{
    const std::string text(bytes.begin(), bytes.end());
    const std::filesystem::path dir = std::filesystem::path(path).parent_path();
    std::string mtl_file;
    const std::string mtl = material_text(text, dir, mtl_file);
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    // tinyobjloader reads the material text only for a file with an mtllib line: give it one.
    const bool has_mtllib = !keyword_values(text, "mtllib").empty();
    if (!reader.ParseFromString(has_mtllib || mtl.empty() ? text : "mtllib materials.mtl\n" + text, mtl, config))
        throw FileError(path, 0, "not a Wavefront OBJ tinyobjloader can read: " + reader.Error());

    Zone zone;
    zone.source.path = path;
    zone.source.format = "Wavefront OBJ";
    for (const tinyobj::material_t& m : reader.GetMaterials())
        zone.materials.push_back(make_material(m, dir));
    const auto default_material = uint32_t(zone.materials.size());
    zone.materials.push_back(Material{"default", 0, 0, {}, 0});
    zone.region_face_offsets.push_back(0);
    ZoneBuilder builder(reader.GetAttrib(), text, path, zone);
    for (const tinyobj::shape_t& shape : reader.GetShapes())
        builder.add_shape(shape, default_material);
    if (zone.mesh.faces.empty())
        throw FileError(path, 0, "the OBJ has no faces: nothing to draw or cull");
    zone.source.counts = {{"objects", zone.regions.size()},
                          {"vertices", reader.GetAttrib().vertices.size() / 3},
                          {"triangles", zone.mesh.triangle_count()},
                          {"materials", reader.GetMaterials().size()}};
    zone.source.notes.push_back(mtl_file.empty() ? "no .mtl found beside it: materials are named, without textures"
                                                 : "materials from " + std::filesystem::path(mtl_file).filename().string());
    zone.source.notes.push_back("objects are the regions (drawable groups); no BSP tree");
    zone.shrink_to_fit();
    return zone;
}

} // namespace pvs
