#include "conformance/io/leb_file.h"

#include "reference/common/byte_stream.h"

namespace voxref::io {

namespace {

// A file of either kind: `parse` (parseLebStream or parseMirroredLebStream) over the mapping, which
// the stream keeps; a corrupt stream's StreamError becomes a FormatError naming the file.
template <class File, class Parse>
File parsedFile(std::shared_ptr<MappedFile> file, const std::filesystem::path& path, Parse&& parse) {
  File f;
  f.file = std::move(file);
  try {
    f.stream = parse(f.file->bytes(), f.file);
  } catch (const ref::StreamError& e) {
    throw FormatError(path.string() + ": " + e.what());
  }
  return f;
}

LebFile parsedLebFile(std::shared_ptr<MappedFile> file, const std::filesystem::path& path) {
  return parsedFile<LebFile>(std::move(file), path, [](std::string_view b, std::shared_ptr<const void> owner) {
    return ref::parseLebStream(b, std::move(owner));
  });
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
  return parsedFile<MirroredLebFile>(std::move(file), path, [](std::string_view b, std::shared_ptr<const void> owner) {
    return ref::parseMirroredLebStream(b, std::move(owner));
  });
}

ref::LebStream readLebFile(const std::filesystem::path& path) { return openLebFile(path).stream; }

void writeLebFile(const std::filesystem::path& path, const std::string& stream) { writeFileAtomically(path, stream); }

}  // namespace voxref::io
