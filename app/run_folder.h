// A command's output folder that holds one run's files only.
//
//   RunFolder folder("out/week", RunFolder::Policy{.force = args.force}, "solve");  // may throw
//   WriteEverything(folder.path());      // a fresh temporary folder beside out/week
//   std::string note = folder.Commit();  // moved into out/week; "" or what was replaced
//
// Every file of a run is written to a temporary folder next to the target
// and moved into place at the end, so an interrupted or failed run leaves the
// target as it was, and a finished one leaves exactly its own files. A target
// that holds an earlier run's files (recorded in its manifest,
// .thrustsched-run.json, or recognised by the names thrustsched writes) is
// refused (ScenarioError, exit 2) unless `force`, in which case the earlier
// run's files are removed first and the caller is told. Files thrustsched did
// not write are never deleted (they stay beside the new run's).
//
// `simulate` writes into its folder as it goes (its checkpoint is the state
// of a resumable run): it uses CheckTarget and RemoveEarlierRun only.
#ifndef THRUSTSCHED_APP_RUN_FOLDER_H_
#define THRUSTSCHED_APP_RUN_FOLDER_H_

#include <string>
#include <vector>

namespace thrustsched::app {

/// What a folder holds.
struct FolderContents {
  bool exists = false;
  /// The files of an earlier thrustsched run (relative paths; a folder such
  /// as simulate's cycles/ is listed as itself).
  std::vector<std::string> run_files;
  std::string run_command;  // from the manifest, "" if unknown
  /// Everything else (never deleted).
  std::vector<std::string> other_files;
  bool holds_run() const { return !run_files.empty(); }
};
FolderContents InspectFolder(const std::string& dir);

/// Removes the earlier run's files (and its manifest); the others stay.
void RemoveEarlierRun(const std::string& dir, const FolderContents& contents);

/// Writes the manifest naming the run's files and the command line.
void WriteManifest(const std::string& dir, const std::vector<std::string>& files,
                   const std::string& command_line);

/// The manifest's file name.
inline constexpr const char* kManifestName = ".thrustsched-run.json";

class RunFolder {
 public:
  /// @throws ScenarioError (exit 2) if `target` holds an earlier run and
  ///         !force, naming the folder, the run and --force; or if the
  ///         folders cannot be created.
  RunFolder(std::string target, bool force, std::string command_line);
  ~RunFolder();  // removes the temporary folder unless committed
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  /// The temporary folder to write into.
  const std::string& path() const { return tmp_; }
  const std::string& target() const { return target_; }
  /// Moves every file written into the target (after removing the earlier
  /// run's files) and writes the manifest. Returns a note for the user when
  /// an earlier run was replaced or other files are present, "" otherwise.
  std::string Commit();

 private:
  std::string target_;
  std::string tmp_;
  std::string command_line_;
  FolderContents before_;
  bool committed_ = false;
};

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_RUN_FOLDER_H_
