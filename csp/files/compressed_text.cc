#include "sightline/csp/files/compressed_text.h"

#include <boost/iostreams/filter/bzip2.hpp>
#include <boost/iostreams/filter/gzip.hpp>
#include <boost/iostreams/filter/lzma.hpp>
#include <boost/iostreams/filtering_stream.hpp>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

#include "sightline/csp/input_error.h"

namespace sightline::csp {

std::string read_possibly_compressed_file(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file)
    throw InputError({path, 0, 0}, std::string("cannot open file: ") + std::strerror(errno));
  unsigned char magic[6] = {0, 0, 0, 0, 0, 0};
  file.read(reinterpret_cast<char*>(magic), sizeof magic);
  const auto got = file.gcount();
  file.clear();
  file.seekg(0);
  namespace io = boost::iostreams;
  io::filtering_istream in;
  std::string compression;
  if (got >= 2 && magic[0] == 0x1f && magic[1] == 0x8b) {
    compression = "gzip";
    in.push(io::gzip_decompressor());
  } else if (got >= 3 && magic[0] == 'B' && magic[1] == 'Z' && magic[2] == 'h') {
    compression = "bzip2";
    in.push(io::bzip2_decompressor());
  } else if (got >= 6 && std::memcmp(magic,
                                     "\xFD"
                                     "7zXZ\0",
                                     6) == 0) {
    compression = "xz";
    in.push(io::lzma_decompressor());
  }
  in.push(file);
  std::string text;
  try {
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  } catch (const std::exception& e) {
    throw InputError({path, 0, 0}, "cannot decompress this " + compression + " file: " + e.what());
  }
  if (in.bad()) {
    throw InputError({path, 0, 0}, compression.empty()
                                       ? "cannot read the file"
                                       : "cannot decompress this " + compression + " file");
  }
  return text;
}

}  // namespace sightline::csp
