#include "io/output_paths.hpp"

#include "core/errors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <sys/stat.h>
#include <unistd.h>

namespace cmp::io {

namespace {

bool is_pattern(const std::string& path) {
  const auto open = path.find('{');
  return open != std::string::npos && path.find('}', open) != std::string::npos;
}

// The pattern with every placeholder replaced by "0": a name of the same folder.
std::string filled(const std::string& path) {
  std::string out;
  for (std::size_t k = 0; k < path.size(); ++k) {
    const auto close = path[k] == '{' ? path.find('}', k) : std::string::npos;
    if (close == std::string::npos) {
      out += path[k];
      continue;
    }
    out += '0';
    k = close;
  }
  return out;
}

std::string folder_of(const std::string& path) {
  const auto dir = std::filesystem::path(path).parent_path().string();
  return dir.empty() ? "." : dir;
}

std::string identity_of_name(const std::string& path) {
  // The folder's device and inode, then the name in it: what rename() will create.
  struct stat dir {};
  if (::stat(folder_of(path).c_str(), &dir) != 0) return {};
  return "n:" + std::to_string(dir.st_dev) + ":" + std::to_string(dir.st_ino) + "/" +
         std::filesystem::path(path).filename().string();
}

// The placeholders of text, in order, each once ("seed" of "s{seed}/r.off").
std::vector<std::string> placeholders(const std::string& text) {
  std::vector<std::string> names;
  for (std::size_t k = text.find('{'); k != std::string::npos; k = text.find('{', k + 1)) {
    const auto close = text.find('}', k);
    if (close == std::string::npos) break;
    const auto name = text.substr(k + 1, close - k - 1);
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

std::string replace_all(std::string text, const std::string& key, const std::string& value) {
  const std::string token = "{" + key + "}";
  for (auto at = text.find(token); at != std::string::npos; at = text.find(token, at + value.size()))
    text.replace(at, token.size(), value);
  return text;
}

// The names a pattern's folders take with the known values (its file name filled with "0"):
// one per distinct folder, at most kMaxFolders of them. Empty when a placeholder of the folder
// has no known values.
constexpr std::size_t kMaxFolders = 100000;
std::vector<std::string> expanded_in_folders(const std::string& pattern, const PlaceholderValues& values) {
  const std::filesystem::path p(pattern);
  const std::string folder = p.parent_path().string(), name = filled(p.filename().string());
  std::vector<std::string> folders{folder};
  for (const auto& key : placeholders(folder)) {
    const auto known = values.find(key);
    if (known == values.end() || known->second.empty()) return {};
    std::vector<std::string> next;
    for (const auto& f : folders)
      for (const auto& v : known->second) {
        if (next.size() >= kMaxFolders) break;
        next.push_back(replace_all(f, key, v));
      }
    std::sort(next.begin(), next.end());
    next.erase(std::unique(next.begin(), next.end()), next.end());
    folders = std::move(next);
  }
  std::vector<std::string> out;
  for (const auto& f : folders) out.push_back((std::filesystem::path(f) / name).string());
  return out;
}

}  // namespace

void check_writable(const std::string& path) {
  if (path == "-") return;
  if (path.empty()) throw InputError(path, 0, "cannot write: empty file name");
  const std::filesystem::path target(path);
  const auto name = target.filename().string();
  if (name.empty() || name == "." || name == "..") throw InputError(path, 0, "cannot write: not a file name");
  struct stat existing {};
  if (::stat(path.c_str(), &existing) == 0 && !S_ISREG(existing.st_mode)) {
    if (S_ISDIR(existing.st_mode)) throw InputError(path, 0, std::string("cannot write: ") + std::strerror(EISDIR));
    if (::access(path.c_str(), W_OK) != 0) throw InputError(path, 0, std::string("cannot write: ") + std::strerror(errno));
    return;
  }
  const auto folder = folder_of(path);
  struct stat st {};
  if (::stat(folder.c_str(), &st) != 0) throw InputError(path, 0, std::string("cannot write: ") + std::strerror(errno));
  if (!S_ISDIR(st.st_mode)) throw InputError(path, 0, std::string("cannot write: ") + std::strerror(ENOTDIR));
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw InputError(path, 0, std::string("cannot write: ") + std::strerror(errno));
  // A name the folder's file system refuses: said now, not when the result is written.
  const long name_max = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  if (name_max > 0 && name.size() > static_cast<std::size_t>(name_max))
    throw InputError(path, 0, fmt::format("cannot write: {} (the name has {} bytes, the folder allows {})",
                                          std::strerror(ENAMETOOLONG), name.size(), name_max));
}

std::string file_identity(const std::string& path) {
  if (path.empty() || path == "-") return {};
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (!S_ISREG(st.st_mode)) return {};
    // An existing file: renaming onto its name replaces it, wherever its links are.
    return "i:" + std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
  }
  return identity_of_name(path);
}

std::vector<PathProblem> output_path_problems(const std::vector<OutputPath>& outputs,
                                              const std::vector<std::string>& inputs,
                                              const PlaceholderValues& values) {
  std::vector<PathProblem> problems;
  std::map<std::string, std::string> input_ids;  // identity -> the input as given
  for (const auto& in : inputs) {
    const auto id = file_identity(in);
    if (!id.empty()) input_ids.emplace(id, in);
  }
  std::map<std::string, std::string> taken;  // identity -> the flag of the first output there
  for (const auto& out : outputs) {
    if (out.path.empty() || out.path == "-") continue;
    const bool pattern = is_pattern(out.path);
    const bool folder_pattern = pattern && is_pattern(std::filesystem::path(out.path).parent_path().string());
    if (folder_pattern) {
      // The folders the pattern names once filled in; each must be writable.
      bool bad = false;
      for (const auto& name : expanded_in_folders(out.path, values)) {
        try {
          check_writable(name);
        } catch (const InputError& e) {
          const std::string what = e.what();
          problems.push_back({out.flag, name + " (from " + out.path + ")" + what.substr(std::min(what.size(), name.size()))});
          bad = true;
          break;
        }
      }
      if (bad) continue;
    } else {
      const auto checked = pattern ? filled(out.path) : out.path;
      try {
        check_writable(checked);
      } catch (const InputError& e) {
        // "path: cannot write: ...", said of the path as given (a pattern, not its filled name)
        const std::string what = e.what();
        problems.push_back({out.flag, out.path + what.substr(std::min(what.size(), checked.size()))});
        continue;
      }
    }
    // A pattern is one family of files: the same pattern in the same folder is the same
    // family; it is compared with fixed names and inputs through no single file.
    const auto id = pattern ? (identity_of_name(out.path).empty() ? "" : "p:" + identity_of_name(out.path))
                            : file_identity(out.path);
    if (id.empty()) continue;
    if (const auto in = input_ids.find(id); in != input_ids.end()) {
      problems.push_back({out.flag, out.path + " is also an input (" + in->second +
                                        "): the output would replace it"});
      continue;
    }
    const auto [at, fresh] = taken.emplace(id, out.flag);
    if (!fresh)
      problems.push_back({out.flag, out.path + " is also the output of " + at->second +
                                        ": two outputs of one run cannot share a file"});
  }
  return problems;
}

}  // namespace cmp::io
