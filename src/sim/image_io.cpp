#include "sim/image_io.hpp"

#include <cmath>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace eco {
namespace {

InputError imageError(const std::filesystem::path& file, const std::string& message) {
  return InputError({file.string(), 0, ""}, message);
}

// Encodes in memory and writes through AtomicFile, which checks every byte reaching the
// disk: OpenImageIO's own file writer does not report a short write of a full disk.
void writeAtomically(const std::filesystem::path& file, OIIO::ImageSpec spec, OIIO::TypeDesc type,
                     const void* pixels) {
  // No time stamp: the same scenario must give byte-identical files.
  spec.attribute("DateTime", "");
  auto out = OIIO::ImageOutput::create(file.string());
  if (!out) throw imageError(file, "cannot write this image format: " + OIIO::geterror());
  if (!out->supports("ioproxy"))
    throw InternalError("OpenImageIO cannot encode " + file.extension().string() + " in memory");
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput memory(encoded);
  out->set_ioproxy(&memory);
  if (!(out->open(file.string(), spec) && out->write_image(type, pixels) && out->close()))
    throw imageError(file, "cannot write image: " + out->geterror());
  AtomicFile target(file);
  target.write(encoded);
  target.commit();
}

}  // namespace

Image readColorImage(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) throw imageError(file, "no such file");
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);  // the colours as stored, not times alpha
  auto in = OIIO::ImageInput::open(file.string(), &config);
  if (!in) throw imageError(file, "cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width > kMaxHeightmapSide || spec.height > kMaxHeightmapSide)
    throw imageError(file, fmt::format("the image is {} x {} pixels, more than {} on a side",
                                       spec.width, spec.height, kMaxHeightmapSide));
  const int channels = spec.nchannels;
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(spec.width) * spec.height * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data()))
    throw imageError(file, "cannot read pixels: " + in->geterror());
  const bool hasAlpha = channels == 2 || channels == 4;
  const bool grey = (hasAlpha ? channels - 1 : channels) == 1;
  Image image(spec.width, spec.height);
  for (std::size_t p = 0; p < static_cast<std::size_t>(spec.width) * spec.height; ++p) {
    const std::uint8_t* pixel = &pixels[p * channels];
    for (int c = 0; c < 3; ++c) image.rgba[p * 4 + c] = pixel[grey ? 0 : c];
    image.rgba[p * 4 + 3] = hasAlpha ? pixel[channels - 1] : 255;
  }
  return image;
}

SingleChannelImage readSingleChannel(const std::filesystem::path& file, bool nanIsNoData) {
  if (!std::filesystem::exists(file)) throw imageError(file, "no such file");
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) throw imageError(file, "cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels != 1)
    throw imageError(file, "expected a single-channel (grey) heightmap, found " +
                               std::to_string(spec.nchannels) + " channels");
  if (spec.width < 2 || spec.height < 2)
    throw imageError(file, "a heightmap needs at least 2 x 2 pixels, found " +
                               std::to_string(spec.width) + " x " + std::to_string(spec.height));
  // The header alone says how large the image claims to be: check before allocating.
  if (spec.width > kMaxHeightmapSide || spec.height > kMaxHeightmapSide)
    throw imageError(file,
                     fmt::format("the image is {} x {} pixels; ecoforest reads heightmaps "
                                 "of at most {} x {} pixels",
                                 spec.width, spec.height, kMaxHeightmapSide, kMaxHeightmapSide));
  SingleChannelImage image;
  image.width = spec.width;
  image.height = spec.height;
  image.values.resize(static_cast<std::size_t>(spec.width) * spec.height);
  if (!in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, image.values.data()))
    throw imageError(file, "cannot read pixels: " + in->geterror());
  // OpenImageIO maps unsigned integers to [0, 1] (and signed to [-1, 1]); undo that so
  // callers see the stored values.
  double scale = 1.0;
  switch (spec.format.basetype) {
    case OIIO::TypeDesc::UINT8:
      scale = 255.0;
      break;
    case OIIO::TypeDesc::UINT16:
      scale = 65535.0;
      break;
    case OIIO::TypeDesc::INT16:
      scale = 32767.0;
      break;
    case OIIO::TypeDesc::UINT32:
      scale = 4294967295.0;
      break;
    default:
      break;
  }
  image.typeMax = scale;
  for (float& v : image.values) {
    if (!std::isfinite(v) && !(nanIsNoData && std::isnan(v)))
      throw imageError(file, "the heightmap contains NaN or infinite pixels");
    if (scale != 1.0) v = static_cast<float>(std::round(v * scale));
  }
  return image;
}

void writeFloatImage(const std::filesystem::path& file, int width, int height, int channels,
                     const std::vector<float>& values) {
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
  writeAtomically(file, spec, OIIO::TypeDesc::FLOAT, values.data());
}

void writeUint16Image(const std::filesystem::path& file, int width, int height,
                      const std::vector<std::uint16_t>& values) {
  OIIO::ImageSpec spec(width, height, 1, OIIO::TypeDesc::UINT16);
  writeAtomically(file, spec, OIIO::TypeDesc::UINT16, values.data());
}

void writeRgb8Image(const std::filesystem::path& file, int width, int height,
                    const std::vector<std::uint8_t>& rgb) {
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  writeAtomically(file, spec, OIIO::TypeDesc::UINT8, rgb.data());
}

void writeRgb8Image(const std::filesystem::path& file, const Image& image) {
  writeRgb8Image(file, image.width, image.height, image.rgb());
}

void writeRgba8Image(const std::filesystem::path& file, const Image& image) {
  OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
  // The colours are not multiplied by alpha: written as they are (PNG's own convention),
  // not divided by alpha as OpenImageIO would for premultiplied pixels.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  writeAtomically(file, spec, OIIO::TypeDesc::UINT8, image.rgba.data());
}

}  // namespace eco
