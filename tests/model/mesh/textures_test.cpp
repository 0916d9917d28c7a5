#include "model/mesh/textures.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace eco {

TEST(Textures, NoiseIsTileableAndInRange) {
  for (float y : {0.1f, 0.5f, 0.77f}) {
    EXPECT_NEAR(tileableNoise(0.0f, y, 4, 3, 9), tileableNoise(1.0f, y, 4, 3, 9), 1e-5f);
    EXPECT_NEAR(tileableNoise(y, 0.0f, 4, 3, 9), tileableNoise(y, 1.0f, 4, 3, 9), 1e-5f);
  }
  for (int i = 0; i < 100; ++i) {
    float n = tileableNoise(i * 0.037f, i * 0.051f, 8, 4, 3);
    EXPECT_GE(n, 0.0f);
    EXPECT_LE(n, 1.0f);
  }
}

TEST(Textures, BarkIsOpaqueAndWrapsAround) {
  Image bark = makeBarkTexture(test::loadNamed("pine").appearance);
  double seam = 0.0, inside = 0.0;
  for (int y = 0; y < bark.height; ++y) {
    EXPECT_EQ(bark.get(0, y).a, 1.0f);
    seam += std::abs(bark.get(0, y).r - bark.get(bark.width - 1, y).r);
    inside += std::abs(bark.get(100, y).r - bark.get(101, y).r);
  }
  // Across the wrap the colour changes no more than between two inner neighbours.
  EXPECT_LT(seam, 2.0 * inside + 1.0);
}

TEST(Textures, LeafIsCutOutAroundTheBlade) {
  Image leaf = makeLeafTexture(test::loadNamed("beech").appearance);
  EXPECT_EQ(leaf.get(2, leaf.height / 2).a, 0.0f);               // beside the blade
  EXPECT_EQ(leaf.get(leaf.width / 2, leaf.height / 2).a, 1.0f);  // the middle of the blade
  EXPECT_EQ(leaf.get(leaf.width / 2, leaf.height - 1).a, 0.0f);  // past the pointed tip
  glm::vec4 mean = leaf.meanOpaqueColor();
  EXPECT_GT(mean.g, mean.r);  // green
  EXPECT_GT(mean.g, mean.b);
}

namespace {

double coverageOf(const Image& image) {
  int opaque = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) opaque += image.get(x, y).a >= 0.5f ? 1 : 0;
  return static_cast<double>(opaque) / (image.width * image.height);
}

}  // namespace

TEST(Textures, CoverageConstantsMatchTheImages) {
  // LOD1 keeps the visible needle area with these constants; they must describe the images.
  Appearance broad = test::loadNamed("beech").appearance;
  Appearance tuft = test::loadNamed("pine").appearance;
  EXPECT_NEAR(coverageOf(makeLeafTexture(broad)), kBroadleafCoverage, 0.01);
  EXPECT_NEAR(coverageOf(makeLeafTexture(tuft)), kNeedleTuftCoverage, 0.01);
  EXPECT_NEAR(coverageOf(makeNeedleTexture(tuft)), kNeedleCoverage, 0.01);
  EXPECT_NEAR(coverageOf(makeNeedleClusterTexture(tuft)), kNeedleClusterCoverage, 0.01);
}

TEST(Textures, MaterialsPerKind) {
  Species beech = test::loadNamed("beech");
  Material leaf = makeMaterial(MaterialKind::Leaf, beech);
  EXPECT_TRUE(leaf.alphaMask);
  EXPECT_TRUE(leaf.doubleSided);
  EXPECT_TRUE(leaf.texture.has_value());
  Material bark = makeMaterial(MaterialKind::Bark, beech);
  EXPECT_FALSE(bark.alphaMask);
  EXPECT_TRUE(bark.repeat);
  Material crown = makeMaterial(MaterialKind::Crown, beech);
  EXPECT_FALSE(crown.texture.has_value());
  EXPECT_EQ(crown.name, "beech_crown");
}

}  // namespace eco
