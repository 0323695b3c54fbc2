#include "conformance/io/leb_file.h"

#include "reference/common/byte_stream.h"

namespace voxref::io {

namespace {

LebFile parsedLebFile(std::shared_ptr<MappedFile> file, const std::filesystem::path& path) {
  LebFile f;
  f.file = std::move(file);
  try {
    f.stream = ref::parseLebStream(f.file->bytes(), f.file);
  } catch (const ref::StreamError& e) {
    throw FormatError(path.string() + ": " + e.what());
  }
  return f;
}

}  // namespace

LebFile openLebFile(const std::filesystem::path& path) {
  auto file = std::make_shared<MappedFile>(MappedFile::openRead(path));
  if (ref::isMirroredLebStream(file->bytes()))
    throw FormatError(path.string() +
                      ": offset 0: magic: 'VXLM', a mirrored stream (reference/leb/FORMAT.md, \"Mirrored streams\"); "
                      "this reads unfolded LEB streams only (voxref decode and voxref info read both)");
  return parsedLebFile(std::move(file), path);
}

std::variant<LebFile, MirroredLebFile> openAnyLebFile(const std::filesystem::path& path) {
  auto file = std::make_shared<MappedFile>(MappedFile::openRead(path));
  if (!ref::isMirroredLebStream(file->bytes())) return parsedLebFile(std::move(file), path);
  MirroredLebFile f;
  f.file = std::move(file);
  try {
    f.stream = ref::parseMirroredLebStream(f.file->bytes(), f.file);
  } catch (const ref::StreamError& e) {
    throw FormatError(path.string() + ": " + e.what());
  }
  return f;
}

ref::LebStream readLebFile(const std::filesystem::path& path) { return openLebFile(path).stream; }

void writeLebFile(const std::filesystem::path& path, const std::string& stream) { writeFileAtomically(path, stream); }

}  // namespace voxref::io
