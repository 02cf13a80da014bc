#include "sightline/domains/camera/level/pk3_archive.h"

#include <zip.h>

#include <algorithm>
#include <cctype>
#include <memory>

#include "sightline/csp/input_error.h"

namespace sightline::camera {

namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::string zip_message(int code) {
  zip_error_t error;
  zip_error_init_with_code(&error, code);
  std::string message = zip_error_strerror(&error);
  zip_error_fini(&error);
  return message;
}

// "maps/a.bsp, maps/b.bsp" -> "a, b".
std::string list_maps(const std::vector<std::string>& entries) {
  std::string out;
  for (const auto& entry : entries) {
    if (!out.empty()) out += ", ";
    out += entry.substr(5, entry.size() - 5 - 4);
  }
  return out;
}

}  // namespace

Pk3Archive::Pk3Archive(std::string path) : path_(std::move(path)) {
  int code = 0;
  archive_ = zip_open(path_.c_str(), ZIP_RDONLY, &code);
  if (archive_ == nullptr) {
    std::string why;
    switch (code) {
      case ZIP_ER_NOENT:
        why = "no such file";
        break;
      case ZIP_ER_NOZIP:
        why = "not a zip archive (a .pk3 is one)";
        break;
      default:
        why = zip_message(code);
    }
    throw csp::InputError(csp::SourceLocation{path_, 0, 0}, "cannot open the .pk3: " + why);
  }
}

Pk3Archive::~Pk3Archive() {
  if (archive_ != nullptr) zip_discard(archive_);  // read only: nothing to write back
}

std::vector<std::string> Pk3Archive::map_entries() const {
  std::vector<std::string> entries;
  const zip_int64_t count = zip_get_num_entries(archive_, 0);
  for (zip_int64_t i = 0; i < count; ++i) {
    const char* name = zip_get_name(archive_, static_cast<zip_uint64_t>(i), ZIP_FL_ENC_GUESS);
    if (name == nullptr) continue;
    const std::string entry = name;
    const std::string low = lower(entry);
    if (low.size() > 9 && low.starts_with("maps/") && low.ends_with(".bsp") &&
        low.find('/', 5) == std::string::npos) {
      entries.push_back(entry);
    }
  }
  std::sort(entries.begin(), entries.end());
  return entries;
}

std::string Pk3Archive::select_map(const std::string& map) const {
  const auto entries = map_entries();
  const csp::SourceLocation where{path_, 0, 0};
  if (entries.empty()) throw csp::InputError(where, "the .pk3 holds no map (maps/*.bsp)");
  if (map.empty()) {
    if (entries.size() == 1) return entries.front();
    throw csp::InputError(where, "the .pk3 holds " + std::to_string(entries.size()) +
                                     " maps: say which with `map` (" + list_maps(entries) + ")");
  }
  std::string wanted = lower(map);
  if (!wanted.starts_with("maps/")) wanted = "maps/" + wanted;
  if (!wanted.ends_with(".bsp")) wanted += ".bsp";
  for (const auto& entry : entries) {
    if (lower(entry) == wanted) return entry;
  }
  throw csp::InputError(where,
                        "no map \"" + map + "\" in the .pk3; it holds: " + list_maps(entries));
}

std::vector<unsigned char> Pk3Archive::read(const std::string& entry) const {
  const csp::SourceLocation where{path_, 0, 0};
  zip_stat_t stat;
  zip_stat_init(&stat);
  if (zip_stat(archive_, entry.c_str(), 0, &stat) != 0 || (stat.valid & ZIP_STAT_SIZE) == 0) {
    throw csp::InputError(where, "no entry " + entry + " in the .pk3");
  }
  if (stat.size > kMaxEntryBytes) {
    throw csp::InputError(where, entry + ": " + std::to_string(stat.size) +
                                     " bytes, more than a map can be: corrupt");
  }
  const std::unique_ptr<zip_file_t, int (*)(zip_file_t*)> file(
      zip_fopen(archive_, entry.c_str(), 0), &zip_fclose);
  if (!file) {
    throw csp::InputError(where, entry + ": cannot read it: " + zip_strerror(archive_));
  }
  std::vector<unsigned char> bytes(static_cast<std::size_t>(stat.size));
  std::size_t done = 0;
  while (done < bytes.size()) {
    const zip_int64_t got = zip_fread(file.get(), bytes.data() + done, bytes.size() - done);
    if (got < 0) {
      throw csp::InputError(
          where, entry + ": corrupt entry: " + zip_error_strerror(zip_file_get_error(file.get())));
    }
    if (got == 0) break;
    done += static_cast<std::size_t>(got);
  }
  if (done != bytes.size()) {
    throw csp::InputError(where, entry + ": corrupt entry: " + std::to_string(done) +
                                     " bytes where the archive promises " +
                                     std::to_string(bytes.size()));
  }
  // libzip checks the CRC once the whole entry is read; a last read at the end reports it.
  unsigned char probe = 0;
  if (zip_fread(file.get(), &probe, 1) < 0) {
    throw csp::InputError(
        where, entry + ": corrupt entry: " + zip_error_strerror(zip_file_get_error(file.get())));
  }
  return bytes;
}

}  // namespace sightline::camera
