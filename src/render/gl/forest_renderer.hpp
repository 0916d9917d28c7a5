// Draws a Forest with a TreeLibrary on the GPU: the meshes it draws in one vertex and one
// index buffer, one impostor atlas per type, and per frame one instance buffer filled
// from the forest's arrays after culling and LOD choice, drawn with one instanced call per
// (type, level, material part) — never a draw call per tree.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/disk_cache.hpp"
#include "core/image.hpp"
#include "render/gl/frame_uniforms.hpp"
#include "render/gl/gl_objects.hpp"
#include "render/gl/shader.hpp"
#include "render/scene/camera.hpp"
#include "render/scene/culling.hpp"
#include "render/scene/forest.hpp"
#include "render/scene/forest_index.hpp"
#include "render/scene/impostor.hpp"
#include "render/scene/render_options.hpp"
#include "render/scene/shadow_cascades.hpp"
#include "render/scene/tree_library.hpp"

namespace eco {

// One tree instance as the shaders read it (attributes 8-11).
struct InstanceAttributes {
  glm::vec4 positionYaw;  // stem base (world), yaw (radians)
  glm::vec4 scale;        // horizontal, vertical, lowest dither threshold kept, wind phase
  glm::vec4 tint;         // rgb; a: the dither thresholds kept end here (ditherKeeps)
  glm::vec2 lean{0.0f};   // the site's lean: multiples of the bend bases (east, south)
};
// A TreeVertex as the GPU holds it, 48 bytes instead of 80: the normal in 10-bit signed
// components, the four wind bases in half floats (millimetres at the metre scale of the
// wind's reach).
struct PackedTreeVertex {
  glm::vec3 position;
  std::uint32_t normal;  // GL_INT_2_10_10_10_REV
  glm::vec2 uv;
  std::uint16_t wind[12];       // swaySin, swayCos, bendEast, bendSouth as half floats
  std::uint16_t skyVisibility;  // 0..65535 for 0..1 (crown_shade.hpp)
  std::uint16_t unused = 0;
};
static_assert(sizeof(PackedTreeVertex) == 52);
PackedTreeVertex packVertex(const TreeVertex& vertex);

// Vertex layouts of the tree shaders: PackedTreeVertex at binding 0, InstanceAttributes at
// binding 1 (one per instance).
void setTreeVertexLayout(GLuint vertexArray);
void setInstanceLayout(GLuint vertexArray);

// What the forest holds on the GPU besides the per-frame instances.
struct ForestGpuMemory {
  std::size_t meshBytes = 0;      // the levels uploaded: packed vertices and indices
  std::size_t impostorBytes = 0;  // the baked atlases with their mip levels
  std::size_t total() const { return meshBytes + impostorBytes; }
};

// A type's level is uploaded, and its impostor atlas baked, when a frame first draws the
// type at that level or as an impostor (or casts its shadow so), in prepare(), not for the
// whole library when the renderer is made: a young run's frames show a fraction of the
// library's types, most of them as impostors, and uploading every level took seconds. The
// glTF export's billboards bake only the two frames they show (bakeFrameImages) and never
// an atlas.
class ForestRenderer {
 public:
  // `uniforms` (the frame uniforms' buffer the shaders read) must outlive the renderer: the
  // atlases are baked through it.
  ForestRenderer(const TreeLibrary& library, const ImpostorSettings& impostors,
                 const FrameUniformBuffer& uniforms);

  // Drops the uploaded meshes after the library's types changed (TreeLibrary::setType), to
  // be uploaded again as frames draw them, the materials kept; the atlases are kept too
  // unless `rebakeImpostors`, which drops them to be baked again (they take longest).
  void reloadMeshes(bool rebakeImpostors);

  // Culls, picks levels and fills the instance buffer for this camera and the shadow
  // cascades (none: no shadows); first uploads the levels it draws that are not yet
  // (ForestStats::meshUploadMs) and bakes the atlases of the types it draws as impostors
  // that have none (ForestStats::impostorBakeMs). With the forest's index (made for it, not
  // another) it looks at each tile's trees only as far down as a pixel can show them: the
  // same frame and counts, in a landscape's overview for a twentieth of the trees.
  ForestStats prepare(const Forest& forest, const Camera& camera, int width, int height,
                      const LodSettings& lod, std::span<const ShadowBox> shadows,
                      const ForestIndex* index = nullptr);
  const TreeLibrary& library() const { return library_; }
  // Called as a frame gets the impostor atlases it needs (read, shared or baked): how many
  // of its sources have theirs, of how many; the last call has done == total. A command's
  // progress line on a terminal: the valley's first frame bakes for 15 s.
  void onAtlasProgress(std::function<void(std::size_t done, std::size_t total)> report) {
    atlasProgress_ = std::move(report);
  }
  const ForestGpuMemory& gpuMemory() const { return gpuMemory_; }
  // The colour pass of what prepare() chose: the meshes (LOD0-2), then the impostors.
  void drawMeshes() const;
  void drawSprites() const;
  // One cascade's shadow casters into the bound depth target.
  void drawShadows(std::size_t cascade) const;

  // The type whose impostor draws `type`: the variants of a species and age class share
  // the first one's. Below the impostor switch (100 px) the variants differ by a few pixels
  // while each tree's own yaw already picks a different frame; sharing bakes a third.
  int impostorSource(int type) const;
  // The level an impostor source's frames show (impostorBakeLevel of its species).
  int bakeLevel(int source) const;
  // Bakes these impostor frames of a type (its source's) as its atlas would hold them and
  // returns their albedo, sRGB with alpha, row 0 at the top (up in the frame's axes,
  // impostor.hpp), tilePixels square; no atlas is kept.
  std::vector<Image> bakeFrameImages(int type, std::span<const glm::ivec2> frames);

 private:
  struct DrawRange {
    MaterialKind material;
    GLsizei count;
    std::uintptr_t firstIndex;
    GLint baseVertex;
  };
  struct Material {
    GlName texture;
    GlName coverage;            // the texture's linear view: the shadow pass reads its alpha alone
    glm::vec4 baseColor{1.0f};  // linear
    bool alphaMask = false;
    bool doubleSided = false;
    float translucency = 0.0f;
  };
  struct Atlas {
    // sRGB albedo with coverage; normal (tree frame) with the translucency; depth: how far
    // a texel lies toward the frame's camera from the plane through the centre, in
    // [-radius, radius] stored as [0, 1], so that an impostor's pixels know where they are.
    GlName albedo, normal, depth;
    GlName extents;  // frameExtentsTexture()
  };
  // Each frame's reach from its centre (frameExtents) at each of the albedo atlas's
  // `levels` mip levels: an R32F array texture, a texel per frame, a layer per mip level.
  // A sprite covers what the mip levels it reads reach, no more.
  GlName frameExtentsTexture(const GlName& albedo, int levels) const;
  struct Bucket {  // instances of one type at one level, contiguous in the instance buffer
    GLuint first = 0;
    GLsizei count = 0;
  };
  using Instance = InstanceAttributes;

  // The instances of `bucket` at a level of a type (uploaded), part by part.
  void drawLevel(int type, int level, Bucket bucket, const Program& program) const;
  // Each type's impostor sprites in bucketOf(type), with its atlases (colour or shadow pass).
  void drawImpostors(const Program& program, float pixelsPerUnit,
                     const std::function<Bucket(std::size_t)>& bucketOf) const;
  // The trees prepare() looks at one by one (considered_): every tree; or, with an index and
  // no level forced, each tile's trees tall enough for minPixels at the tile's nearest point,
  // the others (under it wherever they stand, neither drawn nor casting) counted into
  // `stats` as culled or too small, as prepare() would count them.
  void considerTrees(const Forest& forest, const ForestIndex* index, glm::vec3 eye,
                     const Frustum& frustum, float pixelsPerRadian, const LodSettings& lod,
                     ForestStats& stats);
  // Empties the mesh buffers and makes the vertex arrays that draw from them.
  void resetMeshes();
  // Uploads the levels (type, level) that are not yet, each once; whether any was.
  bool uploadLevels(std::span<const std::pair<int, int>> levels);
  // Bakes the atlases of these impostor sources, each with its atlasKey (and keeps them in
  // the cache, if any).
  void bakeAtlases(const std::vector<std::pair<int, std::uint64_t>>& sources,
                   const std::function<void()>& baked);
  // The key of a source's atlas: everything its texels are made from (the program, the GL
  // that draws, the settings, the mesh it is baked from and its materials). Sources of
  // the same key share an atlas, and the cache keeps it under that key.
  std::uint64_t atlasKey(int source) const;
  // The atlas the cache holds under this key, or null.
  std::shared_ptr<const Atlas> cachedAtlas(std::uint64_t key);
  // An atlas of albedo, normal and depth textures (attachments 0, 1, 2, each frames ×
  // tilePixels square) whose level 0 `fillLevel0` fills, then their mip levels and the
  // frame extents.
  std::shared_ptr<const Atlas> makeAtlas(const std::function<void(int, const GlName&)>& fillLevel0);
  // A target of frames × frames tiles (albedo, normal, depth) and the baking pass's state:
  // one upright instance at the origin, the bake program.
  RenderTarget beginBaking();
  // Draws frames of a type's impostor, each into its tile of the bound target (frames ×
  // frames tiles), which is cleared first.
  void drawImpostorFrames(int type, std::span<const glm::ivec2> frames, const RenderTarget& target);
  void bindMaterial(const Program& program, int species, MaterialKind kind) const;

  const TreeLibrary& library_;
  const FrameUniformBuffer& uniforms_;
  ImpostorSettings impostorSettings_;
  Program meshProgram_, meshShadowProgram_, bakeProgram_, impostorProgram_, impostorShadowProgram_;
  AppendBuffer vertices_, indices_;
  GlName meshArray_, impostorArray_, instances_;
  std::size_t instanceCapacity_ = 0;
  ForestGpuMemory gpuMemory_;
  float pixelsPerUnit_ = 1.0f;  // of the prepared frame: sprite sizes
  std::vector<std::array<std::vector<DrawRange>, kLodCount>> ranges_;  // [type][lod]
  std::vector<std::array<bool, kLodCount>> uploaded_;                  // [type][lod]
  std::vector<std::vector<Material>> materials_;                       // [species][MaterialKind]
  std::vector<std::uint64_t> materialKeys_;  // [species]: its materials' data, for atlasKey
  std::optional<DiskCache> atlasCache_;      // where impostorSettings_.cacheFolder names one
  std::map<std::uint64_t, std::shared_ptr<const Atlas>> atlasesMade_;  // by atlasKey
  std::function<void(std::size_t, std::size_t)> atlasProgress_;
  // [type]: impostor sources only; sources whose atlases are made alike share one.
  std::vector<std::shared_ptr<const Atlas>> atlases_;
  std::vector<Bucket> buckets_;  // [type * kLevelCount + level]
  // Shadow casters, per cascade: in the nearest each tree casts with the level it is drawn
  // at; trees outside the view, and every tree in the coarser cascades (whose texels are
  // decimetres to metres), cast as impostor sprites seen from the sun.
  static constexpr std::uint8_t kNoCaster = 0;  // else 1 + the level it casts with
  std::vector<Bucket> shadowBuckets_;           // [(cascade * types + type) * kLevelCount + level]
  std::vector<float> shadowPixelsPerMetre_;     // [cascade]
  // Scratch of prepare(), kept to avoid reallocating every frame.
  std::vector<std::uint32_t> considered_;  // forest indices; the arrays below are by place here
  std::vector<LodChoice> choices_;
  std::vector<std::uint8_t> casts_;  // [tree * cascades + cascade]
  std::vector<float> distances_;
  std::vector<std::uint32_t> order_;
  std::vector<Instance> staging_;
};

}  // namespace eco
