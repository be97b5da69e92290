// Image-space accuracy on hand-made inputs whose answers follow from the definitions.
#include "visibility/eval/image_accuracy.h"

#include <gtest/gtest.h>

namespace pvs {
namespace {

// Three regions; faces: 0 (1 triangle) in region 0; 1 (2 triangles) in regions 0 and 1;
// 2 (4 triangles) in region 2.
Zone three_regions()
{
    Zone z;
    z.regions.resize(3);
    z.mesh.faces = {{0, 1, 0}, {1, 2, 0}, {3, 4, 0}};
    z.region_face_offsets = {0, 2, 3, 4};
    z.region_faces = {0, 1, 1, 2};
    return z;
}

TEST(ImageAccuracy, FaceRegionsInvertTheRegionLists)
{
    const Zone z = three_regions();
    const FaceRegions fr = build_face_regions(z);
    EXPECT_EQ(std::vector<uint32_t>(fr.of(0).begin(), fr.of(0).end()), std::vector<uint32_t>{0});
    EXPECT_EQ(std::vector<uint32_t>(fr.of(1).begin(), fr.of(1).end()), (std::vector<uint32_t>{0, 1}));
    EXPECT_EQ(std::vector<uint32_t>(fr.of(2).begin(), fr.of(2).end()), std::vector<uint32_t>{2});
}

TEST(ImageAccuracy, PixelsOfFacesNoKeptRegionListsPop)
{
    const Zone z = three_regions();
    const FaceRegions fr = build_face_regions(z);
    // 6 pixels: background, face 0 twice, face 1, face 2 twice. Kept: region 1 only.
    const std::vector<int32_t> ids{-1, 0, 0, 1, 2, 2};
    const std::vector<uint32_t> kept{1};
    const ImageAccuracy a = measure_image_accuracy(z, fr, ids, kept);
    EXPECT_EQ(a.pixels, 6u);
    EXPECT_EQ(a.covered_pixels, 5u);
    EXPECT_EQ(a.popping_pixels, 4u); // face 1 is drawn through region 1; faces 0 and 2 are not
    EXPECT_EQ(a.popping_faces, (std::vector<uint32_t>{0, 2}));
    EXPECT_EQ(a.popping_regions, (std::vector<uint32_t>{0, 2}));
    EXPECT_EQ(a.needed_faces, 3u);
    EXPECT_EQ(a.needed_triangles, 7u);
    EXPECT_EQ(a.needed_regions, 3u);
    EXPECT_EQ(a.drawn_triangles, 2u);
    EXPECT_EQ(a.drawn_regions, 1u);
}

TEST(ImageAccuracy, DrawingEverythingNeverPopsAndOverdrawCountsTheRest)
{
    const Zone z = three_regions();
    const FaceRegions fr = build_face_regions(z);
    const std::vector<int32_t> ids{0, 0, 99}; // 99: not a face of this zone, counted as background
    const std::vector<uint32_t> kept{0, 1, 2};
    const ImageAccuracy a = measure_image_accuracy(z, fr, ids, kept);
    EXPECT_EQ(a.covered_pixels, 2u);
    EXPECT_EQ(a.popping_pixels, 0u);
    EXPECT_EQ(a.needed_triangles, 1u);
    EXPECT_EQ(a.drawn_triangles, 7u);
    EXPECT_DOUBLE_EQ(a.triangle_overdraw(), 7.0);
    EXPECT_DOUBLE_EQ(a.region_overdraw(), 3.0);
}

} // namespace
} // namespace pvs
