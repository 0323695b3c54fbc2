#include "conformance/io/image_io.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "conformance/io/atomic_file.h"

namespace voxref::io {

void writePng(const std::filesystem::path& path, const Rgb8Image& image) {
  if (image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3)
    throw IoError("image for " + path.string() + " has the wrong number of pixels");
  // OIIO's PNG writer does not report a failing write (a full disk gave a truncated PNG that it
  // called written): encode into memory, then write the bytes with checked writes, atomically.
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  auto file = OIIO::ImageOutput::create("png");
  if (!file || !file->supports("ioproxy"))
    throw IoError("cannot write " + path.string() + ": OpenImageIO has no PNG writer to memory " + OIIO::geterror());
  const OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  if (!file->set_ioproxy(&memory) || !file->open(path.string(), spec) ||
      !file->write_image(OIIO::TypeDesc::UINT8, image.rgb.data()) || !file->close())
    throw IoError("cannot encode " + path.string() + ": " + file->geterror());
  writeFileAtomically(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

void writeExr(const std::filesystem::path& path, int width, int height, const std::vector<ExrChannel>& channels,
              const std::map<std::string, std::string>& attributes) {
  for (const ExrChannel& c : channels)
    if ((c.uintData.empty() ? c.data.size() : c.uintData.size()) != static_cast<std::size_t>(width) * height)
      throw IoError("channel " + c.name + " for " + path.string() + " has the wrong number of pixels");
  AtomicOutput out(path);
  try {
    Imf::Header header(width, height);
    for (const auto& [key, value] : attributes) header.insert(key, Imf::StringAttribute(value));
    Imf::FrameBuffer fb;
    for (const ExrChannel& c : channels) {
      if (!c.uintData.empty()) {
        header.channels().insert(c.name, Imf::Channel(Imf::UINT));
        fb.insert(c.name, Imf::Slice(Imf::UINT, reinterpret_cast<char*>(const_cast<std::uint32_t*>(c.uintData.data())),
                                     sizeof(std::uint32_t), sizeof(std::uint32_t) * static_cast<std::size_t>(width)));
        continue;
      }
      header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
      fb.insert(c.name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(c.data.data())),
                                   sizeof(float), sizeof(float) * static_cast<std::size_t>(width)));
    }
    Imf::OutputFile file(out.temporary().c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(height);
  } catch (const std::exception& e) {
    throw IoError("cannot write " + path.string() + ": " + e.what());
  }
  out.commit();
}

}  // namespace voxref::io
