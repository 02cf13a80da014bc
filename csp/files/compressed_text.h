// Reading a whole text file that may be compressed, for the toulbar2 readers (.wcsp, .cfn).
//
// toulbar2's instances are often distributed gzip'd or xz'd (`.wcsp.gz`, `.cfn.xz`). The
// compression is recognised by the file's first bytes (gzip, bzip2, xz), whatever its name,
// and undone on the fly with Boost.Iostreams, which is linked here only.
#pragma once

#include <string>

namespace sightline::csp {

// The file's text, decompressed if needed. Throws InputError naming the file when it cannot
// be opened, read or decompressed.
std::string read_possibly_compressed_file(const std::string& path);

}  // namespace sightline::csp
