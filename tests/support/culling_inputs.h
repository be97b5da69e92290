// Random inputs for the culler's stages, shared by their exactness tests: frustums looking
// anywhere over a 1000-unit cube, a grid of box regions with the odd boxes a zone can hold, and
// rows of a given density. Deterministic for a seeded generator.
#pragma once

#include "visibility/bit_row.h"
#include "visibility/math/aabb.h"
#include "visibility/math/frustum.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace pvs::test {

// A perspective frustum from a random eye towards a random point, far plane at `far`.
inline Frustum random_frustum(std::mt19937& rng, float far)
{
    std::uniform_real_distribution<float> u(-500.0f, 500.0f), fov(30.0f, 110.0f), aspect(0.6f, 2.0f);
    const glm::vec3 eye{u(rng), u(rng), u(rng)};
    glm::vec3 at{u(rng), u(rng), u(rng)};
    if (glm::length(at - eye) < 1.0f)
        at += glm::vec3(10.0f, 0.0f, 0.0f);
    const glm::mat4 proj = glm::perspective(glm::radians(fov(rng)), aspect(rng), 1.0f, far);
    return Frustum::from_view_projection(proj * glm::lookAt(eye, at, glm::vec3(0, 0, 1)));
}

// n x n x n/2 cells of 40 units, x fastest (neighbouring ids lie together) or shuffled (as outdoor
// zones), with an empty box (3) and two that are not finite (70, 71).
inline std::vector<Aabb> grid_boxes(std::mt19937& rng, int n, bool shuffled)
{
    std::vector<Aabb> boxes;
    for (int z = 0; z < n / 2; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                boxes.push_back({glm::vec3(x, y, z) * 40.0f - 400.0f, glm::vec3(x + 1, y + 1, z + 1) * 40.0f - 400.0f});
    if (shuffled)
        std::shuffle(boxes.begin(), boxes.end(), rng);
    boxes[3] = Aabb{};                                        // empty
    boxes[70].max.x = std::numeric_limits<float>::infinity(); // not finite
    boxes[71].min.y = std::numeric_limits<float>::quiet_NaN();
    return boxes;
}

// n bits, each set with probability `density`.
inline std::vector<uint64_t> random_row(std::mt19937& rng, size_t n, double density)
{
    std::vector<uint64_t> row(bits::words_for(n), 0);
    std::bernoulli_distribution pick(density);
    for (size_t i = 0; i < n; ++i)
        if (pick(rng))
            bits::set(row, i);
    return row;
}

} // namespace pvs::test
