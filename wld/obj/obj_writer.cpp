#include "wld/obj/obj_writer.h"

#include "visibility/file_error.h"
#include "wld/common/read_file.h"
#include "wld/eq/stb_image_io.h"

#include <cctype>
#include <cstdio>
#include <filesystem>

namespace pvs {

namespace {

std::string safe_name(const std::string& name, size_t index)
{
    std::string out;
    for (char c : name)
        out.push_back(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' ? c : '_');
    return out.empty() ? "material_" + std::to_string(index) : out;
}

void append_float(std::string& out, float v)
{
    char text[32];
    std::snprintf(text, sizeof text, " %.6g", double(v));
    out += text;
}

} // namespace

ObjExport export_obj(const Zone& zone, const std::string& base_name)
{
    ObjExport e;
    e.obj = "# pvscope export of " + zone.source.path + " (" + zone.source.format + ")\n";
    e.obj += "# z-up zone written y-up as (x, z, -y); one object per region\n";
    e.obj += "mtllib " + base_name + ".mtl\n";
    std::vector<std::string> material_names(zone.materials.size());
    for (size_t m = 0; m < zone.materials.size(); ++m) {
        material_names[m] = safe_name(zone.materials[m].name, m) + "_" + std::to_string(m);
        e.mtl += "newmtl " + material_names[m] + "\nKd 1 1 1\n";
        if (zone.materials[m].has_pixels()) {
            const std::string bmp = base_name + "_" + material_names[m] + ".bmp";
            e.mtl += "map_Kd " + bmp + "\n";
            e.textures.emplace_back(bmp, m);
        }
        e.mtl += "\n";
    }
    const Mesh& mesh = zone.mesh;
    for (const glm::vec3& p : mesh.positions) {
        e.obj += "v";
        append_float(e.obj, p.x);
        append_float(e.obj, p.z);
        append_float(e.obj, -p.y);
        e.obj += "\n";
    }
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec2 uv = i < mesh.uvs.size() ? mesh.uvs[i] : glm::vec2(0.0f);
        e.obj += "vt";
        append_float(e.obj, uv.x);
        append_float(e.obj, 1.0f - uv.y); // OBJ's v runs up, image rows run down
        e.obj += "\n";
    }
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        e.obj += "o " + (r < zone.region_names.size() ? zone.region_names[r] : "region_" + std::to_string(r)) + "\n";
        uint32_t current = UINT32_MAX;
        for (uint32_t f : zone.faces_of_region(r)) {
            const Face& face = mesh.faces[f];
            if (face.material != current) {
                current = face.material;
                e.obj += "usemtl " + material_names[current] + "\n";
            }
            for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t) {
                e.obj += "f";
                for (int k = 0; k < 3; ++k) {
                    const std::string i = std::to_string(mesh.indices[3 * size_t(t) + size_t(k)] + 1);
                    e.obj += " " + i + "/" + i;
                }
                e.obj += "\n";
            }
        }
    }
    return e;
}

void save_obj(const Zone& zone, const std::string& obj_path)
{
    const std::filesystem::path path(obj_path);
    const std::string base = path.stem().string();
    const ObjExport e = export_obj(zone, base);
    write_whole_file(obj_path, std::vector<uint8_t>(e.obj.begin(), e.obj.end()));
    const std::filesystem::path dir = path.parent_path();
    const std::string mtl_path = (dir / (base + ".mtl")).string();
    write_whole_file(mtl_path, std::vector<uint8_t>(e.mtl.begin(), e.mtl.end()));
    for (const auto& [bmp, m] : e.textures) {
        const Material& material = zone.materials[m];
        write_whole_file((dir / bmp).string(), encode_bmp(material.width, material.height, material_rgba(material)));
    }
}

} // namespace pvs
