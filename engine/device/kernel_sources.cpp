#include "device/kernel_sources.h"

#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <unordered_map>

#include "util/error.h"

namespace gdr {
namespace {

const std::string* find_file(const std::string& path) {
  static const std::unordered_map<std::string, const std::string*> index = [] {
    std::unordered_map<std::string, const std::string*> m;
    for (const EmbeddedKernelFile& f : embedded_kernel_files()) m[f.path] = &f.text;
    return m;
  }();
  auto it = index.find(path);
  return it == index.end() ? nullptr : it->second;
}

std::string normalize(const std::string& path) {
  return std::filesystem::path(path).lexically_normal().generic_string();
}

// Parses `#include "name"`; returns false for any other line.
bool parse_include(const std::string& line, std::string& name) {
  size_t i = line.find_first_not_of(" \t");
  if (i == std::string::npos || line[i] != '#') return false;
  i = line.find_first_not_of(" \t", i + 1);
  if (i == std::string::npos || line.compare(i, 7, "include") != 0) return false;
  size_t open = line.find('"', i + 7);
  if (open == std::string::npos) return false;
  size_t close = line.find('"', open + 1);
  if (close == std::string::npos) return false;
  name = line.substr(open + 1, close - open - 1);
  return true;
}

bool is_pragma_once(const std::string& line) {
  std::istringstream s(line);
  std::string a, b;
  s >> a >> b;
  return (a == "#pragma" && b == "once");
}

void expand(const std::string& path, std::set<std::string>& included, std::ostringstream& out) {
  if (!included.insert(path).second) return;
  const std::string* text = find_file(path);
  if (!text) throw Error("kernel source not found: kernels/" + path);
  std::istringstream in(*text);
  std::string line;
  int number = 0;
  out << "#line 1 \"kernels/" << path << "\"\n";
  while (std::getline(in, line)) {
    ++number;
    std::string name;
    if (parse_include(line, name)) {
      std::string local = normalize((std::filesystem::path(path).parent_path() / name).string());
      std::string target = find_file(local) ? local : normalize(name);
      if (!find_file(target)) {
        throw Error("kernels/" + path + ":" + std::to_string(number) + ": included file not found: " + name);
      }
      expand(target, included, out);
      out << "#line " << number + 1 << " \"kernels/" << path << "\"\n";
    } else if (is_pragma_once(line)) {
      out << "\n";
    } else {
      out << line << "\n";
    }
  }
}

}  // namespace

std::string resolve_kernel_source(const std::string& root) {
  std::set<std::string> included;
  std::ostringstream out;
  expand(normalize(root), included, out);
  return out.str();
}

std::string name_resolved_lines(const std::string& log, const std::string& resolved) {
  // The original place of each resolved line, from the #line markers: places[n - 1] for line n.
  std::vector<std::string> places;
  std::istringstream in(resolved);
  std::string line, file = "<kernel>";
  long next = 1;
  static const std::regex marker(R"re(^#line (\d+) "([^"]*)"\s*$)re");
  for (std::smatch m; std::getline(in, line);) {
    places.push_back(file + ":" + std::to_string(next++));
    if (std::regex_match(line, m, marker)) {
      next = std::stol(m[1].str());
      file = m[2].str();
    }
  }
  static const std::regex place(R"(<kernel>:(\d+):)");
  std::string out;
  auto from = log.cbegin();
  for (std::sregex_iterator it(log.begin(), log.end(), place), end; it != end; ++it) {
    const size_t n = std::stoul((*it)[1].str());
    out.append(from, (*it)[0].first);
    out += (n >= 1 && n <= places.size() ? places[n - 1] : "<kernel>:" + std::to_string(n)) + ":";
    from = (*it)[0].second;
  }
  return out.append(from, log.cend());
}

}  // namespace gdr
