#include "app/run_folder.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "app/json_reader.h"  // ScenarioError

namespace thrustsched::app {
namespace {

namespace fs = std::filesystem;

// Every name a thrustsched command writes into its folder (solve, check,
// simulate, transfer), for runs older than the manifest.
const std::set<std::string>& KnownNames() {
  static const std::set<std::string> names = {
      "summary.json", "schedule.csv", "trajectory.csv", "impulses.csv",    "check.json",
      "gnuplot.log",  "window.gp",    "window.svg",     "timeline.gp",     "timeline.svg",
      "outputs.gp",   "outputs.svg",  "consumption.gp", "consumption.svg", "vectors.gp",
      "vectors.svg",  "latlon.gp",    "latlon.svg",     "checkpoint.json", "in_progress.json",
      "year.json",    "cycles.csv",   "cycles",         "xy.gp",           "xy.svg",
      "report.html",  "gap.gp",       "gap.svg",        "thrust_days.gp",  "thrust_days.svg",
      "box.gp",       "box.svg",      "orbit.csv",      "elements.gp",     "elements.svg",
      "orbit.gp",     "orbit.svg"};
  return names;
}

// A folder holds a run if it has one of these.
bool IsRunMarker(const std::string& name) {
  return name == kManifestName || name == "summary.json" || name == "check.json" ||
         name == "checkpoint.json" || name == "year.json";
}

std::string JoinFirst(const std::vector<std::string>& names, size_t most) {
  std::string s;
  for (size_t i = 0; i < names.size() && i < most; ++i) s += (i ? ", " : "") + names[i];
  if (names.size() > most) s += ", ...";
  return s;
}

void RemoveOrThrow(const fs::path& p) {
  std::error_code ec;
  fs::remove_all(p, ec);
  if (ec)
    throw ScenarioError(p.string() + ": cannot remove the earlier run's file (" + ec.message() +
                        ")");
}

}  // namespace

FolderContents InspectFolder(const std::string& dir) {
  FolderContents c;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return c;
  c.exists = true;
  std::vector<std::string> names;
  bool marked = false;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    names.push_back(name);
    marked = marked || IsRunMarker(name);
  }
  std::sort(names.begin(), names.end());
  std::set<std::string> listed;
  const fs::path manifest = fs::path(dir) / kManifestName;
  if (fs::exists(manifest)) {
    try {
      std::ifstream in(manifest);
      const nlohmann::json j = nlohmann::json::parse(in);
      for (const auto& f : j.at("files")) listed.insert(f.get<std::string>());
      c.run_command = j.value("command_line", "");
    } catch (const std::exception&) {
      listed.clear();  // unreadable: fall back to the known names
    }
  }
  const std::set<std::string>& known = listed.empty() ? KnownNames() : listed;
  for (const std::string& name : names) {
    if (name == kManifestName) continue;
    if (marked && known.count(name) > 0) {
      c.run_files.push_back(name);
    } else {
      c.other_files.push_back(name);
    }
  }
  if (marked && c.run_files.empty()) c.run_files.push_back(kManifestName);
  return c;
}

void RemoveEarlierRun(const std::string& dir, const FolderContents& contents) {
  for (const std::string& name : contents.run_files) RemoveOrThrow(fs::path(dir) / name);
  std::error_code ec;
  fs::remove(fs::path(dir) / kManifestName, ec);
}

void WriteManifest(const std::string& dir, const std::vector<std::string>& files,
                   const std::string& command_line) {
  nlohmann::json j;
  j["written_by"] = "thrustsched";
  j["command_line"] = command_line;
  j["files"] = files;
  std::ofstream out(fs::path(dir) / kManifestName, std::ios::binary);
  out << j.dump(2) << "\n";
  if (!out) throw ScenarioError(dir + ": cannot write " + kManifestName);
}

RunFolder::RunFolder(std::string target, bool force, std::string command_line)
    : target_(std::move(target)), command_line_(std::move(command_line)) {
  before_ = InspectFolder(target_);
  if (before_.holds_run() && !force) {
    throw ScenarioError(target_ + " holds the results of an earlier run (" +
                        JoinFirst(before_.run_files, 4) +
                        (before_.run_command.empty() ? "" : "; from: " + before_.run_command) +
                        "): use --force to replace them, or choose another --out");
  }
  fs::path t = fs::absolute(fs::path(target_)).lexically_normal();
  if (t.filename().empty()) t = t.parent_path();
  std::error_code ec;
  fs::create_directories(t.parent_path(), ec);
  std::string pattern =
      (t.parent_path() / ("." + t.filename().string() + ".thrustsched-tmp-XXXXXX")).string();
  if (mkdtemp(pattern.data()) == nullptr) {
    throw ScenarioError(target_ + ": cannot create a temporary folder beside it (" +
                        std::string(std::strerror(errno)) + ")");
  }
  tmp_ = pattern;
  // mkdtemp makes it private (0700); the results are made as any new folder.
  const mode_t mask = umask(0);
  umask(mask);
  fs::permissions(tmp_, static_cast<fs::perms>(0777 & ~mask), ec);
}

RunFolder::~RunFolder() {
  if (committed_ || tmp_.empty()) return;
  std::error_code ec;
  fs::remove_all(tmp_, ec);
}

std::string RunFolder::Commit() {
  std::vector<std::string> files;
  for (const fs::directory_entry& e : fs::directory_iterator(tmp_)) {
    files.push_back(e.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  std::ostringstream note;
  const FolderContents now = InspectFolder(target_);  // it may have changed since
  if (!now.exists) {
    WriteManifest(tmp_, files, command_line_);
    std::error_code ec;
    fs::rename(tmp_, target_, ec);
    if (!ec) {
      committed_ = true;
      return "";
    }
    fs::create_directories(target_, ec);  // e.g. created meanwhile: move file by file
  }
  if (now.holds_run()) {
    RemoveEarlierRun(target_, now);
    note << "replaced the earlier run's " << now.run_files.size() << " file(s) in " << target_;
  }
  for (const std::string& f : files) {
    std::error_code ec;
    const fs::path dest = fs::path(target_) / f;
    if (fs::is_directory(dest)) fs::remove_all(dest, ec);
    fs::rename(fs::path(tmp_) / f, dest, ec);
    if (ec)
      throw ScenarioError(dest.string() + ": cannot move the result into place (" + ec.message() +
                          ")");
  }
  WriteManifest(target_, files, command_line_);
  std::error_code ec;
  fs::remove(tmp_, ec);
  committed_ = true;
  if (!now.other_files.empty()) {
    note << (note.tellp() > 0 ? "; " : "") << target_ << " also holds " << now.other_files.size()
         << " file(s) thrustsched did not write, left as they are ("
         << JoinFirst(now.other_files, 4) << ")";
  }
  return note.str();
}

}  // namespace thrustsched::app
