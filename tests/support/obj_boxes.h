// Hand-made OBJ text for tests: closed boxes whose six sides face inward (rooms), written in the
// OBJ's y-up axes (zone (x, y, z) is file (x, z, -y), as obj_reader.h reads it back).
#pragma once

#include <glm/vec3.hpp>

#include <string>

namespace pvs::test {

// One object `name`: the box lo..hi (zone coordinates), counter-clockwise seen from inside.
// first_vertex is the file's next vertex number (1 for the first box) and is advanced by 8.
inline std::string closed_box_object(const std::string& name, const glm::vec3& lo, const glm::vec3& hi,
                                     int& first_vertex)
{
    std::string text = "o " + name + "\n";
    const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                            {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    for (const glm::vec3& p : c)
        text += "v " + std::to_string(p.x) + " " + std::to_string(p.z) + " " + std::to_string(-p.y) + "\n";
    const int quads[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 5, 6, 2}};
    for (const auto& q : quads)
        text += "f " + std::to_string(first_vertex + q[0]) + " " + std::to_string(first_vertex + q[1]) + " " +
                std::to_string(first_vertex + q[2]) + " " + std::to_string(first_vertex + q[3]) + "\n";
    first_vertex += 8;
    return text;
}

// Room A (x 0..100) and room B (x 110..210), both y 0..100 and z 0..50, rock between them.
inline std::string two_closed_rooms_obj()
{
    int v = 1;
    std::string text = closed_box_object("room_a", {0, 0, 0}, {100, 100, 50}, v);
    text += closed_box_object("room_b", {110, 0, 0}, {210, 100, 50}, v); // after room_a: v counts on
    return text;
}

} // namespace pvs::test
