#include "render/gl/forest_renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

#include "core/error.hpp"
#include "core/stopwatch.hpp"
#include "model/mesh/textures.hpp"

namespace eco {
namespace {

constexpr int kMaterialKinds = 5;

glm::vec3 linearFromSrgb(glm::vec3 c) {
  return glm::pow(c, glm::vec3(2.2f));
}

}  // namespace

PackedTreeVertex packVertex(const TreeVertex& v) {
  PackedTreeVertex p;
  p.position = v.position;
  p.normal = glm::packSnorm3x10_1x2(glm::vec4(v.normal, 0.0f));
  p.uv = v.uv;
  const glm::vec3* bases[] = {&v.swaySin, &v.swayCos, &v.bendEast, &v.bendSouth};
  for (int b = 0; b < 4; ++b)
    for (int c = 0; c < 3; ++c) p.wind[b * 3 + c] = glm::packHalf1x16((*bases[b])[c]);
  p.skyVisibility = glm::packUnorm1x16(v.skyVisibility);
  return p;
}

void setTreeVertexLayout(GLuint vao) {
  glEnableVertexArrayAttrib(vao, 0);
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(PackedTreeVertex, position));
  glEnableVertexArrayAttrib(vao, 1);
  glVertexArrayAttribFormat(vao, 1, 4, GL_INT_2_10_10_10_REV, GL_TRUE,
                            offsetof(PackedTreeVertex, normal));
  glEnableVertexArrayAttrib(vao, 2);
  glVertexArrayAttribFormat(vao, 2, 2, GL_FLOAT, GL_FALSE, offsetof(PackedTreeVertex, uv));
  for (GLuint b = 0; b < 4; ++b) {  // the wind bases, attributes 3-6
    glEnableVertexArrayAttrib(vao, 3 + b);
    glVertexArrayAttribFormat(vao, 3 + b, 3, GL_HALF_FLOAT, GL_FALSE,
                              offsetof(PackedTreeVertex, wind) + b * 3 * sizeof(std::uint16_t));
  }
  glEnableVertexArrayAttrib(vao, 7);
  glVertexArrayAttribFormat(vao, 7, 1, GL_UNSIGNED_SHORT, GL_TRUE,
                            offsetof(PackedTreeVertex, skyVisibility));
  for (GLuint a = 0; a < 8; ++a) glVertexArrayAttribBinding(vao, a, 0);
}

// Instance attributes 8-11 come from binding 1, one element per instance.
void setInstanceLayout(GLuint vao) {
  for (GLuint a = 0; a < 4; ++a) {
    glEnableVertexArrayAttrib(vao, 8 + a);
    glVertexArrayAttribFormat(vao, 8 + a, a < 3 ? 4 : 2, GL_FLOAT, GL_FALSE, a * sizeof(glm::vec4));
    glVertexArrayAttribBinding(vao, 8 + a, 1);
  }
  glVertexArrayBindingDivisor(vao, 1, 1);
}

ForestRenderer::ForestRenderer(const TreeLibrary& library, const ImpostorSettings& impostors,
                               const FrameUniformBuffer& uniforms)
    : library_(library),
      uniforms_(uniforms),
      impostorSettings_(impostors),
      meshProgram_({{GL_VERTEX_SHADER, "tree.vert"}, {GL_FRAGMENT_SHADER, "tree.frag"}}),
      meshShadowProgram_({{GL_VERTEX_SHADER, "tree.vert"}, {GL_FRAGMENT_SHADER, "tree.frag"}},
                         {"SHADOW_PASS"}),
      bakeProgram_({{GL_VERTEX_SHADER, "tree.vert"}, {GL_FRAGMENT_SHADER, "tree.frag"}}, {"BAKE"}),
      impostorProgram_(
          {{GL_VERTEX_SHADER, "impostor.vert"}, {GL_FRAGMENT_SHADER, "impostor.frag"}}),
      impostorShadowProgram_(
          {{GL_VERTEX_SHADER, "impostor.vert"}, {GL_FRAGMENT_SHADER, "impostor.frag"}},
          {"SHADOW_PASS"}) {
  resetMeshes();
  if (!impostors.cacheFolder.empty() && programIdentity())
    atlasCache_.emplace(impostors.cacheFolder);

  // Materials of each species, textures generated as the exporters do (in parallel: the
  // procedural textures take a moment each), then uploaded.
  const std::size_t speciesCount = library.species().size();
  std::vector<eco::Material> sources(speciesCount * kMaterialKinds);
  tbb::parallel_for(std::size_t{0}, sources.size(), [&](std::size_t i) {
    sources[i] = makeMaterial(static_cast<MaterialKind>(i % kMaterialKinds),
                              library.species()[i / kMaterialKinds]);
  });
  for (std::size_t s = 0; s < speciesCount; ++s) {
    std::vector<Material>& kinds = materials_.emplace_back(kMaterialKinds);
    CacheKey key;
    for (int k = 0; k < kMaterialKinds; ++k) {
      const auto kind = static_cast<MaterialKind>(k);
      const eco::Material& source = sources[s * kMaterialKinds + k];
      if (source.texture)
        key.addValue(source.texture->width)
            .addValue(source.texture->height)
            .add(std::string_view(reinterpret_cast<const char*>(source.texture->rgba.data()),
                                  source.texture->rgba.size()));
      key.addValue(source.baseColor).addValue(source.alphaMask).addValue(source.doubleSided);
      key.addValue(source.repeat);
      Material& m = kinds[k];
      if (source.texture) {
        m.texture = makeTexture(*source.texture, source.repeat);
        m.coverage = makeLinearView(m.texture);
      }
      m.baseColor = glm::vec4(linearFromSrgb(glm::vec3(source.baseColor)), source.baseColor.a);
      m.alphaMask = source.alphaMask;
      m.doubleSided = source.doubleSided;
      // Thin leaves pass light; bark and the closed crown proxies do not.
      m.translucency = kind == MaterialKind::Bark || kind == MaterialKind::Crown ? 0.0f : 0.35f;
    }
    materialKeys_.push_back(key.value());
  }
}

void ForestRenderer::bindMaterial(const Program& program, int species, MaterialKind kind) const {
  const Material& m = materials_[species][static_cast<int>(kind)];
  program.set("uBaseColor", m.baseColor);
  program.set("uHasTexture", m.texture ? 1 : 0);
  program.set("uAlphaMask", m.alphaMask ? 1 : 0);
  program.set("uTranslucency", m.translucency);
  program.set("uLeafyNoise", kind == MaterialKind::Crown ? 1 : 0);
  const bool coverageOnly = &program == &meshShadowProgram_;
  if (m.texture) glBindTextureUnit(0, coverageOnly ? m.coverage.id() : m.texture.id());
  if (m.doubleSided)
    glDisable(GL_CULL_FACE);
  else
    glEnable(GL_CULL_FACE);
}

void ForestRenderer::drawLevel(int type, int level, Bucket bucket, const Program& program) const {
  if (bucket.count == 0) return;
  const int species = library_.type(type).species;
  for (const DrawRange& range : ranges_[type][level]) {
    bindMaterial(program, species, range.material);
    glDrawElementsInstancedBaseVertexBaseInstance(GL_TRIANGLES, range.count, GL_UNSIGNED_INT,
                                                  reinterpret_cast<const void*>(range.firstIndex),
                                                  bucket.count, range.baseVertex, bucket.first);
  }
}

void ForestRenderer::resetMeshes() {
  vertices_ = AppendBuffer();
  indices_ = AppendBuffer();
  ranges_.assign(library_.typeCount(), {});
  uploaded_.assign(library_.typeCount(), {});
  gpuMemory_.meshBytes = 0;
  GLuint id = 0;
  glCreateBuffers(1, &id);
  instances_ = GlName(GlKind::Buffer, id);
  meshArray_ = makeVertexArray();
  setTreeVertexLayout(meshArray_.id());
  setInstanceLayout(meshArray_.id());
  impostorArray_ = makeVertexArray();  // instance attributes only: one sprite per tree
  setInstanceLayout(impostorArray_.id());
  instanceCapacity_ = 0;  // the instance buffer is new and empty
  atlases_.resize(library_.typeCount());
}

bool ForestRenderer::uploadLevels(std::span<const std::pair<int, int>> levels) {
  // Appended to the buffers together: each append may copy what they hold.
  std::vector<PackedTreeVertex> vertices;
  std::vector<std::uint32_t> indices;
  const std::size_t firstVertex = vertices_.size() / sizeof(PackedTreeVertex);
  const std::size_t firstIndex = indices_.size() / sizeof(std::uint32_t);
  for (const auto& [type, lod] : levels) {
    if (uploaded_[type][lod]) continue;
    uploaded_[type][lod] = true;
    for (const WindPart& part : library_.type(type).meshes.lods[lod].parts) {
      ranges_[type][lod].push_back({part.material, static_cast<GLsizei>(part.indices.size()),
                                    (firstIndex + indices.size()) * sizeof(std::uint32_t),
                                    static_cast<GLint>(firstVertex + vertices.size())});
      for (const TreeVertex& v : part.vertices) vertices.push_back(packVertex(v));
      indices.insert(indices.end(), part.indices.begin(), part.indices.end());
    }
  }
  if (vertices.empty()) return false;
  vertices_.append(std::span<const PackedTreeVertex>(vertices));
  indices_.append(std::span<const std::uint32_t>(indices));
  gpuMemory_.meshBytes = vertices_.size() + indices_.size();
  glVertexArrayVertexBuffer(meshArray_.id(), 0, vertices_.id(), 0, sizeof(PackedTreeVertex));
  glVertexArrayElementBuffer(meshArray_.id(), indices_.id());
  return true;
}

void ForestRenderer::reloadMeshes(bool rebakeImpostors) {
  resetMeshes();
  if (rebakeImpostors) {
    atlases_.clear();
    atlases_.resize(library_.typeCount());
    atlasesMade_.clear();
    gpuMemory_.impostorBytes = 0;
  }
}

int ForestRenderer::impostorSource(int type) const {
  return library_.impostorSource(type);
}

int ForestRenderer::bakeLevel(int source) const {
  const int species = library_.type(source).species;
  return impostorBakeLevel(library_.species()[species], impostorSettings_.bakeLod);
}

namespace {

// One tile of a baked frames texture, rows top-down, transparent texels in the tile's mean
// colour so that a client filtering the picture keeps the tree's colour at its edges
// instead of darkening them.
Image frameImageOf(const GlName& texture, glm::ivec2 frame, int tile) {
  Image image(tile, tile);
  std::vector<std::uint8_t> rows(image.rgba.size());
  glGetTextureSubImage(texture.id(), 0, frame.x * tile, frame.y * tile, 0, tile, tile, 1, GL_RGBA,
                       GL_UNSIGNED_BYTE, static_cast<GLsizei>(rows.size()), rows.data());
  // OpenGL's rows run bottom-up.
  const std::size_t stride = static_cast<std::size_t>(tile) * 4;
  for (int y = 0; y < tile; ++y)
    std::copy_n(rows.begin() + static_cast<std::ptrdiff_t>((tile - 1 - y) * stride), stride,
                image.rgba.begin() + static_cast<std::ptrdiff_t>(y * stride));
  const glm::vec4 mean = image.meanOpaqueColor();
  for (int y = 0; y < tile; ++y)
    for (int x = 0; x < tile; ++x)
      if (image.get(x, y).a < 0.5f) image.set(x, y, glm::vec4(glm::vec3(mean), image.get(x, y).a));
  return image;
}

}  // namespace

GlName ForestRenderer::frameExtentsTexture(const GlName& albedo, int levels) const {
  const int frames = impostorSettings_.frames, tile = impostorSettings_.tilePixels;
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
  GlName texture(GlKind::Texture, id);
  glTextureStorage3D(id, 1, GL_R32F, frames, frames, levels);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  for (int level = 0; level < levels; ++level) {
    // The coverage of the mip level as the sprites read it (8 bits, after filtering).
    const int size = frames * (tile >> level);
    std::vector<std::uint8_t> rgba(std::size_t{4} * size * size);
    glGetTextureImage(albedo.id(), level, GL_RGBA, GL_UNSIGNED_BYTE,
                      static_cast<GLsizei>(rgba.size()), rgba.data());
    std::vector<std::uint8_t> alpha(rgba.size() / 4);
    for (std::size_t i = 0; i < alpha.size(); ++i) alpha[i] = rgba[4 * i + 3];
    const std::vector<float> extents = frameExtents(alpha, frames, tile >> level);
    glTextureSubImage3D(id, 0, 0, 0, level, frames, frames, 1, GL_RED, GL_FLOAT, extents.data());
  }
  return texture;
}

std::vector<Image> ForestRenderer::bakeFrameImages(int type, std::span<const glm::ivec2> frames) {
  const int tile = impostorSettings_.tilePixels;
  const int source = impostorSource(type);
  const std::array<std::pair<int, int>, 1> level{{{source, bakeLevel(source)}}};
  uploadLevels(level);
  const RenderTarget target = beginBaking();
  drawImpostorFrames(source, frames, target);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  std::vector<Image> images;
  for (const glm::ivec2 frame : frames) images.push_back(frameImageOf(target.color, frame, tile));
  return images;
}

RenderTarget ForestRenderer::beginBaking() {
  const int size = impostorSettings_.frames * impostorSettings_.tilePixels;
  RenderTarget target = RenderTarget::create(size, size, 2);
  const Instance identity{glm::vec4(0.0f), glm::vec4(1.0f, 1.0f, 0.0f, 0.0f), glm::vec4(1.0f),
                          glm::vec2(0.0f)};
  glNamedBufferData(instances_.id(), sizeof(Instance), &identity, GL_DYNAMIC_DRAW);
  instanceCapacity_ = 1;
  glVertexArrayVertexBuffer(meshArray_.id(), 1, instances_.id(), 0, sizeof(Instance));
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_FRAMEBUFFER_SRGB);
  glBindVertexArray(meshArray_.id());
  bakeProgram_.use();
  return target;
}

void ForestRenderer::drawImpostorFrames(int type, std::span<const glm::ivec2> frames,
                                        const RenderTarget& target) {
  const TreeType& tree = library_.type(type);
  const int tile = impostorSettings_.tilePixels;
  const glm::vec3 centre(tree.bounds);
  const float radius = tree.bounds.w;
  target.bind();
  // Every attachment holds its value times the coverage (drawn texels cover fully, the
  // rest are zero), so that filtering and the mip levels average each over what covers a
  // texel only: the shader divides by the coverage (albedo's alpha). An unweighted mean
  // would pull the colours toward a clear colour and the normals toward a clear normal.
  const glm::vec4 none(0.0f);
  const float farDepth = 1.0f;
  for (int attachment = 0; attachment < 3; ++attachment)
    glClearNamedFramebufferfv(target.framebuffer.id(), GL_COLOR, attachment, &none.x);
  glClearNamedFramebufferfv(target.framebuffer.id(), GL_DEPTH, 0, &farDepth);
  for (const glm::ivec2 frame : frames) {
    const glm::vec3 f = frameDirection(frame, impostorSettings_.frames);
    glm::vec3 right, up;
    frameAxes(f, right, up);
    FrameUniforms u;
    const glm::mat4 view = glm::lookAt(centre + 2.0f * radius * f, centre, up);
    u.viewProj = glm::ortho(-radius, radius, -radius, radius, 0.0f, 4.0f * radius) * view;
    u.camera = glm::vec4(centre + 100.0f * radius * f, 0.0f);
    uniforms_.upload(u);
    // OpenGL's convention throughout: row 0 at the bottom of the atlas, up is +v.
    glViewport(frame.x * tile, frame.y * tile, tile, tile);
    drawLevel(type, bakeLevel(type), {0, 1}, bakeProgram_);
  }
}

void ForestRenderer::bakeAtlases(const std::vector<std::pair<int, std::uint64_t>>& sources,
                                 const std::function<void()>& baked) {
  const int frames = impostorSettings_.frames, tile = impostorSettings_.tilePixels;
  const int size = frames * tile;
  std::vector<glm::ivec2> all;
  for (int row = 0; row < frames; ++row)
    for (int column = 0; column < frames; ++column) all.push_back({column, row});
  const RenderTarget target = beginBaking();
  const GlName* drawn[] = {&target.color, &target.extraColors[0], &target.extraColors[1]};
  for (const auto& [t, key] : sources) {
    drawImpostorFrames(t, all, target);
    const std::shared_ptr<const Atlas> atlas =
        makeAtlas([&](int attachment, const GlName& texture) {
          glCopyImageSubData(drawn[attachment]->id(), GL_TEXTURE_2D, 0, 0, 0, 0, texture.id(),
                             GL_TEXTURE_2D, 0, 0, 0, 0, size, size, 1);
        });
    atlases_[t] = atlasesMade_[key] = atlas;
    baked();
    if (!atlasCache_) continue;
    // Kept as the level-0 texels of the three, from which makeAtlas makes the same atlas.
    const std::size_t bytes = std::size_t{4} * size * size;
    std::string texels(3 * bytes, '\0');
    const GlName* made[] = {&atlas->albedo, &atlas->normal, &atlas->depth};
    for (int i = 0; i < 3; ++i)
      glGetTextureImage(made[i]->id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(bytes),
                        texels.data() + i * bytes);
    atlasCache_->write(key, texels);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::shared_ptr<const ForestRenderer::Atlas> ForestRenderer::makeAtlas(
    const std::function<void(int, const GlName&)>& fillLevel0) {
  const int size = impostorSettings_.frames * impostorSettings_.tilePixels;
  const int levels = 1 + static_cast<int>(std::log2(impostorSettings_.tilePixels));  // to 1 texel
  auto make = [&](int attachment, GLenum format) {
    GlName texture = makeTextureStorage(format, size, size, levels);
    fillLevel0(attachment, texture);
    glGenerateTextureMipmap(texture.id());
    return texture;
  };
  auto atlas = std::make_shared<Atlas>();
  // Three RGBA8 textures; a full mip chain adds a third.
  gpuMemory_.impostorBytes += 3 * std::size_t{4} * size * size * 4 / 3;
  atlas->albedo = make(0, GL_SRGB8_ALPHA8);
  atlas->normal = make(1, GL_RGBA8);
  atlas->depth = make(2, GL_RGBA8);
  atlas->extents = frameExtentsTexture(atlas->albedo, levels);
  return atlas;
}

std::uint64_t ForestRenderer::atlasKey(int source) const {
  const TreeType& type = library_.type(source);
  const int level = bakeLevel(source);
  CacheKey key;
  // The program's identity tells builds apart in the cache (which the constructor makes
  // only where there is one); within one renderer, sharing atlases, it is not needed, and
  // hashing the executable is left out of the renderers that keep no cache.
  key.add("impostor atlas").addValue(atlasCache_ ? *programIdentity() : std::uint64_t{0});
  for (const GLenum name : {GL_VENDOR, GL_RENDERER, GL_VERSION})
    key.add(reinterpret_cast<const char*>(glGetString(name)));
  key.addValue(impostorSettings_.frames).addValue(impostorSettings_.tilePixels).addValue(level);
  key.addValue(type.bounds).addValue(materialKeys_[type.species]);
  std::vector<PackedTreeVertex> packed;
  for (const WindPart& part : type.meshes.lods[level].parts) {
    packed.clear();
    for (const TreeVertex& v : part.vertices) packed.push_back(packVertex(v));
    key.addValue(part.material)
        .add(std::string_view(reinterpret_cast<const char*>(packed.data()),
                              packed.size() * sizeof(PackedTreeVertex)))
        .add(std::string_view(reinterpret_cast<const char*>(part.indices.data()),
                              part.indices.size() * sizeof(std::uint32_t)));
  }
  return key.value();
}

std::shared_ptr<const ForestRenderer::Atlas> ForestRenderer::cachedAtlas(std::uint64_t key) {
  if (!atlasCache_) return nullptr;
  const std::optional<std::string> texels = atlasCache_->read(key);
  const int size = impostorSettings_.frames * impostorSettings_.tilePixels;
  const std::size_t bytes = std::size_t{4} * size * size;
  if (!texels || texels->size() != 3 * bytes) return nullptr;
  return makeAtlas([&](int attachment, const GlName& texture) {
    glTextureSubImage2D(texture.id(), 0, 0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE,
                        texels->data() + attachment * bytes);
  });
}

void ForestRenderer::considerTrees(const Forest& forest, const ForestIndex* index, glm::vec3 eye,
                                   const Frustum& frustum, float pixelsPerRadian,
                                   const LodSettings& lod, ForestStats& stats) {
  considered_.clear();
  if (!index || lod.forcedLevel >= 0) {
    considered_.resize(forest.size());
    std::iota(considered_.begin(), considered_.end(), std::uint32_t{0});
    return;
  }
  ECO_ASSERT(index->forestSize() == forest.size(), "a forest drawn with another forest's index");
  const std::vector<ForestIndex::Tile>& tiles = index->tiles();
  const std::vector<ForestIndex::Group>& groups = index->groups();
  // Per group: does a frame look at its trees? Per tile: how many it looks at, how many it
  // passes over that are outside the view.
  std::vector<std::uint8_t> looked(groups.size(), 0);
  std::vector<std::uint32_t> lookedAt(tiles.size() + 1, 0), culled(tiles.size(), 0);
  tbb::parallel_for(std::size_t{0}, tiles.size(), [&](std::size_t t) {
    const ForestIndex::Tile& tile = tiles[t];
    // No tree of the tile is nearer than its box: a group whose tallest tree cannot reach
    // minPixels there is under it wherever its trees stand in the tile.
    const float nearest = glm::distance(glm::clamp(eye, tile.lo, tile.hi), eye);
    const Frustum::Side side = frustum.sideOfBox(tile.lo, tile.hi, 0.05f);
    for (std::uint32_t g = tile.firstGroup; g < tile.lastGroup; ++g) {
      const ForestIndex::Group& group = groups[g];
      if (mayReachMinPixels(group.tallest, nearest, pixelsPerRadian, lod)) {
        looked[g] = 1;
        lookedAt[t + 1] += group.last - group.first;
      } else if (side == Frustum::Side::Outside) {
        culled[t] += group.last - group.first;
      } else if (side == Frustum::Side::Across) {  // their spheres one by one, as prepare's
        for (std::uint32_t k = group.first; k < group.last; ++k) {
          const std::uint32_t i = index->trees()[k];
          const glm::vec4 bounds = drawnBounds(forest, i, library_.type(forest.type[i]));
          culled[t] += !frustum.intersectsSphere(glm::vec3(bounds), bounds.w);
        }
      }
    }
  });
  std::partial_sum(lookedAt.begin(), lookedAt.end(), lookedAt.begin());
  considered_.resize(lookedAt.back());
  tbb::parallel_for(std::size_t{0}, tiles.size(), [&](std::size_t t) {
    auto out = considered_.begin() + lookedAt[t];
    for (std::uint32_t g = tiles[t].firstGroup; g < tiles[t].lastGroup; ++g)
      if (looked[g])
        out = std::copy(index->trees().begin() + groups[g].first,
                        index->trees().begin() + groups[g].last, out);
  });
  const std::size_t passed = forest.size() - considered_.size();
  const std::size_t outside = std::accumulate(culled.begin(), culled.end(), std::size_t{0});
  stats.culled += outside;
  stats.tooSmall += passed - outside;
}

ForestStats ForestRenderer::prepare(const Forest& forest, const Camera& camera, int width,
                                    int height, const LodSettings& lod,
                                    std::span<const ShadowBox> shadows, const ForestIndex* index) {
  ForestStats stats;
  const auto types = static_cast<std::size_t>(library_.typeCount());
  const Frustum frustum =
      Frustum::fromMatrix(camera.projection(static_cast<float>(width) / height) * camera.view());
  const float pixelsPerRadian = camera.pixelsPerRadian(height);
  pixelsPerUnit_ = pixelsPerRadian;
  const std::size_t cascades = shadows.size();
  shadowPixelsPerMetre_.clear();
  for (const ShadowBox& box : shadows) shadowPixelsPerMetre_.push_back(box.mapPixelsPerMetre);
  // The trees looked at one by one: considered_[j] is tree j's index in the forest, and
  // choices_, distances_, `outside` and casts_ are by j.
  considerTrees(forest, index, camera.position, frustum, pixelsPerRadian, lod, stats);
  const std::size_t n = considered_.size();
  stats.lookedAt = n;
  choices_.assign(n, LodChoice{});
  casts_.assign(n * cascades, kNoCaster);
  std::vector<std::uint8_t> outside(n, 0);
  distances_.resize(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&](const auto& range) {
    for (std::size_t j = range.begin(); j != range.end(); ++j) {
      const std::size_t i = considered_[j];
      const TreeType& type = library_.type(forest.type[i]);
      const glm::vec4 bounds = drawnBounds(forest, i, type);
      const glm::vec3 centre(bounds);
      const float radius = bounds.w;
      const float distance = glm::length(centre - camera.position);
      distances_[j] = distance;
      const float height_m = type.height_m * forest.scaleY[i];
      const float pixels = projectedPixels(height_m, distance, pixelsPerRadian);
      const bool inView = frustum.intersectsSphere(centre, radius);
      if (inView) choices_[j] = chooseLevel(pixels, lod);
      outside[j] = !inView;
      // A tree casts into each cascade whose map its crown reaches (shadowHeldBy; also from
      // outside the view: its shadow may fall into it) and whose texels it covers. In the nearest
      // it casts with the level it is drawn at (the finer of a cross-fade), so its shadow has the
      // gaps and the density of the crown the viewer sees; elsewhere as a sprite. Only a tree whose
      // shadow can reach the view casts: the sphere around the crown's shadow on level ground below
      // the stem base (swept from the crown along the sun by its height over the sun's elevation)
      // must meet the frustum.
      bool shadowInView = false;
      if (cascades > 0) {
        const glm::vec3 toSun = shadows[0].toSun;
        const float drop = height_m + radius;
        const float length = drop / std::max(toSun.y, 0.02f);
        shadowInView =
            frustum.intersectsSphere(centre - toSun * (0.5f * length), radius + 0.5f * length);
      }
      // A tree whose shadow a finer map holds whole casts into no coarser one: every point
      // under it reads that finer map (of 300,000 trees over the valley, a twentieth of the
      // coarser maps' fragments).
      for (std::size_t k = 0; shadowInView && k < cascades; ++k) {
        const ShadowBox& box = shadows[k];
        if (box.halfSize_m <= 0.0f || pixels < lod.minPixels ||
            height_m * box.mapPixelsPerMetre < 1.0f)
          continue;
        const MapHolds held = shadowHeldBy(box, centre, radius);
        if (held == MapHolds::none) continue;
        const int level = k == 0 && inView ? choices_[j].level : kLevelImpostor;
        if (level < 0) continue;
        casts_[j * cascades + k] = static_cast<std::uint8_t>(1 + level);
        if (held == MapHolds::all) break;
      }
    }
  });

  // Buckets in a fixed order (type, level), trees front to back within each (ties by
  // index): near trees fill the depth buffer first, so the depth test rejects most hidden
  // fragments of the ones behind before they are shaded — a third of the frame at 300k
  // trees. A total order, so the frame does not depend on the thread count.
  buckets_.assign(types * kLevelCount, Bucket{});
  shadowBuckets_.assign(cascades * types * kLevelCount, Bucket{});
  // The bucket of tree j's caster in cascade c, or null where it casts none there.
  auto shadowBucket = [&](std::size_t j, std::size_t c) -> Bucket* {
    const std::uint8_t caster = casts_[j * cascades + c];
    if (caster == kNoCaster) return nullptr;
    return &shadowBuckets_[(c * types + forest.type[considered_[j]]) * kLevelCount + caster - 1];
  };
  auto castsAny = [&](std::size_t j) {
    for (std::size_t c = 0; c < cascades; ++c)
      if (casts_[j * cascades + c] != kNoCaster) return true;
    return false;
  };
  // Every draw of tree j: its type (and the type it blends into) split its presence range,
  // and a level cross-fade splits each type's range again.
  auto forEachDraw = [&](std::size_t j, auto&& draw) {
    const std::size_t i = considered_[j];
    const LodChoice& c = choices_[j];
    const float presence = forest.presence[i];
    const float split = presence * (forest.blendType[i] >= 0 ? 1.0f - forest.blendWeight[i] : 1.0f);
    // `scale` turns the tree's scales, meant for its own type's mesh, to another type's.
    auto levels = [&](int type, float scale, float lo, float hi) {
      if (hi <= lo) return;
      if (c.fadeTo < 0) return draw(type, c.level, scale, lo, hi);
      const float cut = lo + c.fade * (hi - lo);  // the coarser level takes the lower share
      if (hi > cut) draw(type, c.level, scale, cut, hi);
      if (cut > lo) draw(type, c.fadeTo, scale, lo, cut);
    };
    levels(forest.type[i], 1.0f, 0.0f, split);
    if (forest.blendType[i] >= 0)
      levels(forest.blendType[i],
             library_.typeHeight_m(forest.type[i]) / library_.typeHeight_m(forest.blendType[i]),
             split, presence);
  };
  for (std::size_t j = 0; j < n; ++j) {
    if (outside[j])
      ++stats.culled;
    else if (choices_[j].level < 0)
      ++stats.tooSmall;
    for (std::size_t c = 0; c < cascades; ++c)
      if (Bucket* bucket = shadowBucket(j, c)) ++bucket->count;
    if (choices_[j].level < 0) continue;
    forEachDraw(j, [&](int type, int level, float, float, float) {
      ++buckets_[type * kLevelCount + level].count;
    });
  }
  {
    // The levels this frame is the first to draw, and the atlases of the types it is the
    // first to draw as impostors or shadow sprites (each baked from its source's level
    // bakeLod), made before the instances are uploaded: baking draws with an instance of
    // its own.
    std::vector<std::pair<int, int>> levels;
    std::vector<std::uint8_t> sprites(types, 0);
    for (std::size_t t = 0; t < types; ++t)
      for (int level = 0; level < kLevelCount; ++level) {
        bool drawn = buckets_[t * kLevelCount + level].count > 0;
        for (std::size_t c = 0; c < cascades; ++c)
          drawn = drawn || shadowBuckets_[(c * types + t) * kLevelCount + level].count > 0;
        if (!drawn) continue;
        if (level < kLevelImpostor)
          levels.emplace_back(static_cast<int>(t), level);
        else
          sprites[impostorSource(static_cast<int>(t))] = 1;
      }
    // A source takes the atlas of another made alike (the same key: a young tree's crown
    // classes, pruned of branches it does not have yet), else the cache's, else it needs its
    // level to bake from; one of each key is baked.
    const auto bakeStart = std::chrono::steady_clock::now();
    std::vector<std::pair<int, std::uint64_t>> unbaked, sharing;
    std::size_t needed = 0, done = 0;  // sources drawn without an atlas yet; given theirs
    for (std::size_t t = 0; t < types; ++t) needed += sprites[t] && !atlases_[t];
    const auto given = [&] {
      if (atlasProgress_) atlasProgress_(++done, needed);
    };
    for (std::size_t t = 0; t < types; ++t) {
      if (!sprites[t] || atlases_[t]) continue;
      const auto source = static_cast<int>(t);
      const std::uint64_t key = atlasKey(source);
      if (const auto made = atlasesMade_.find(key); made != atlasesMade_.end()) {
        atlases_[t] = made->second;
        given();
      } else if (std::shared_ptr<const Atlas> cached = cachedAtlas(key)) {
        atlases_[t] = atlasesMade_[key] = std::move(cached);
        ++stats.impostorAtlasesCached;
        given();
      } else if (std::any_of(unbaked.begin(), unbaked.end(),
                             [&](const auto& u) { return u.second == key; })) {
        sharing.emplace_back(source, key);
      } else {
        unbaked.emplace_back(source, key);
        levels.emplace_back(source, bakeLevel(source));
      }
    }
    // Zero where nothing was needed: a frame with setup time is not measured (view).
    if (needed > 0) stats.impostorBakeMs = millisecondsSince(bakeStart);
    const auto uploadStart = std::chrono::steady_clock::now();
    if (uploadLevels(levels)) stats.meshUploadMs = millisecondsSince(uploadStart);
    if (!unbaked.empty()) {
      const auto drawStart = std::chrono::steady_clock::now();
      bakeAtlases(unbaked, given);
      stats.impostorBakeMs += millisecondsSince(drawStart);
      stats.impostorAtlasesBaked = unbaked.size();
    }
    for (const auto& [t, key] : sharing) {
      atlases_[t] = atlasesMade_.at(key);
      given();
    }
  }
  GLuint next = 0;
  for (Bucket& b : buckets_) b.first = next, next += b.count, b.count = 0;
  for (Bucket& b : shadowBuckets_) b.first = next, next += b.count, b.count = 0;
  staging_.resize(next);
  order_.clear();
  for (std::size_t j = 0; j < n; ++j)
    if (choices_[j].level >= 0 || castsAny(j)) order_.push_back(static_cast<std::uint32_t>(j));
  tbb::parallel_sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t b) {
    return distances_[a] < distances_[b] ||
           (distances_[a] == distances_[b] && considered_[a] < considered_[b]);
  });
  for (const std::uint32_t j : order_) {
    const std::size_t i = considered_[j];
    auto put = [&](Bucket& bucket, float scale, float lo, float hi) {
      staging_[bucket.first + bucket.count++] = {
          glm::vec4(forest.position[i], forest.yaw[i]),
          glm::vec4(scale * forest.scaleXZ[i], scale * forest.scaleY[i], lo, forest.phase[i]),
          glm::vec4(forest.tint[i], hi), forest.lean[i]};
    };
    if (choices_[j].level >= 0)
      forEachDraw(j, [&](int type, int level, float scale, float lo, float hi) {
        put(buckets_[type * kLevelCount + level], scale, lo, hi);
      });
    for (std::size_t c = 0; c < cascades; ++c)
      if (Bucket* bucket = shadowBucket(j, c)) put(*bucket, 1.0f, 0.0f, forest.presence[i]);
  }
  if (staging_.size() > instanceCapacity_) {
    instanceCapacity_ = std::max<std::size_t>(staging_.size() + staging_.size() / 2, 1024);
    glNamedBufferData(instances_.id(), instanceCapacity_ * sizeof(Instance), nullptr,
                      GL_STREAM_DRAW);
  }
  glNamedBufferSubData(instances_.id(), 0, staging_.size() * sizeof(Instance), staging_.data());

  for (std::size_t t = 0; t < types; ++t)
    for (int level = 0; level < kLevelCount; ++level) {
      const std::size_t count = buckets_[t * kLevelCount + level].count;
      if (count == 0) continue;
      const auto& lods = library_.type(static_cast<int>(t)).meshes.lods;
      stats.instances[level] += count;
      stats.triangles += count * (level < kLevelImpostor ? lods[level].triangleCount() : 2);
      stats.lod0Triangles += count * lods[0].triangleCount();
    }
  for (std::size_t b = 0; b < shadowBuckets_.size(); ++b)
    stats.shadowCasters[b % kLevelCount] += shadowBuckets_[b].count;
  return stats;
}

void ForestRenderer::drawMeshes() const {
  glBindVertexArray(meshArray_.id());
  glVertexArrayVertexBuffer(meshArray_.id(), 1, instances_.id(), 0, sizeof(Instance));
  meshProgram_.use();
  for (int t = 0; t < library_.typeCount(); ++t)
    for (int level = 0; level < kLevelImpostor; ++level)
      drawLevel(t, level, buckets_[t * kLevelCount + level], meshProgram_);
}

void ForestRenderer::drawSprites() const {
  drawImpostors(impostorProgram_, pixelsPerUnit_,
                [&](std::size_t t) { return buckets_[t * kLevelCount + kLevelImpostor]; });
}

void ForestRenderer::drawImpostors(const Program& program, float pixelsPerUnit,
                                   const std::function<Bucket(std::size_t)>& bucketOf) const {
  glEnable(GL_PROGRAM_POINT_SIZE);
  glBindVertexArray(impostorArray_.id());
  glVertexArrayVertexBuffer(impostorArray_.id(), 1, instances_.id(), 0, sizeof(Instance));
  program.use();
  program.set("uFrames", impostorSettings_.frames);
  program.set("uBlendFrames", impostorSettings_.blendFrames ? 1 : 0);
  program.set("uPixelsPerUnit", pixelsPerUnit);
  program.set("uTilePixels", impostorSettings_.tilePixels);
  program.set("uCropSprites", impostorSettings_.cropSprites ? 1 : 0);
  for (int t = 0; t < library_.typeCount(); ++t) {
    const Bucket bucket = bucketOf(t);
    if (bucket.count == 0) continue;
    const int source = impostorSource(t);
    program.set("uBounds", library_.type(source).bounds);
    const Atlas& atlas = *atlases_[source];
    glBindTextureUnit(1, atlas.albedo.id());
    glBindTextureUnit(2, atlas.normal.id());
    glBindTextureUnit(5, atlas.depth.id());
    glBindTextureUnit(9, atlas.extents.id());
    glDrawArraysInstancedBaseInstance(GL_POINTS, 0, 1, bucket.count, bucket.first);
  }
}

void ForestRenderer::drawShadows(std::size_t cascade) const {
  const std::size_t first = cascade * library_.typeCount() * kLevelCount;
  glBindVertexArray(meshArray_.id());
  glVertexArrayVertexBuffer(meshArray_.id(), 1, instances_.id(), 0, sizeof(Instance));
  meshShadowProgram_.use();
  for (int t = 0; t < library_.typeCount(); ++t)
    for (int level = 0; level < kLevelImpostor; ++level)
      drawLevel(t, level, shadowBuckets_[first + t * kLevelCount + level], meshShadowProgram_);

  drawImpostors(impostorShadowProgram_, shadowPixelsPerMetre_[cascade], [&](std::size_t t) {
    return shadowBuckets_[first + t * kLevelCount + kLevelImpostor];
  });
}

}  // namespace eco
