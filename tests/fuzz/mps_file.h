// milp::ReadMpsFile reads a path (CoinMpsIO opens the file itself), so the
// MPS harnesses write each input to one temporary file per process.
//
//   milp::LpData lp = fuzz::ReadMpsText(text);   // @throws as ReadMpsFile
#ifndef THRUSTSCHED_TESTS_FUZZ_MPS_FILE_H_
#define THRUSTSCHED_TESTS_FUZZ_MPS_FILE_H_

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "milp/lp_data.h"
#include "milp/mps_reader.h"

namespace thrustsched::fuzz {

inline const std::string& MpsTempPath() {
  static const std::string path = (std::filesystem::temp_directory_path() /
                                   ("thrustsched_fuzz_" + std::to_string(getpid()) + ".mps"))
                                      .string();
  return path;
}

inline milp::LpData ReadMpsText(std::string_view text) {
  {
    std::ofstream out(MpsTempPath(), std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  }
  return milp::ReadMpsFile(MpsTempPath());
}

}  // namespace thrustsched::fuzz

#endif  // THRUSTSCHED_TESTS_FUZZ_MPS_FILE_H_
