// Shared by the libFuzzer harnesses of tests/fuzz/ (one per input parser):
// the bad-input contract and the shipped files the harnesses start from.
//
//   extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
//     fuzz::ExpectContract([&] { app::ParseOpm(fuzz::Text(data, size), "fuzz.opm"); });
//     return 0;
//   }
//
// The contract of every reader: it returns, or throws its documented
// bad-input error (std::invalid_argument, of which app::ScenarioError, the
// CLI's exit 2). Anything else (another exception, a crash, a sanitizer
// report, an input over 1 s, an allocation over 2 GB) is a finding: the
// exception is left to escape, so that libFuzzer (or the replay main,
// replay_main.cc) aborts on it with the input.
#ifndef THRUSTSCHED_TESTS_FUZZ_FUZZ_COMMON_H_
#define THRUSTSCHED_TESTS_FUZZ_FUZZ_COMMON_H_

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace thrustsched::fuzz {

inline std::string_view Text(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Runs `parse`; true if it returned, false if it threw the documented
/// std::invalid_argument. Other exceptions propagate (a finding).
template <class F>
bool ExpectContract(F&& parse) {
  try {
    parse();
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

/// A shipped file under data/ (THRUSTSCHED_DATA_DIR). Aborts if absent:
/// a harness without its base files would fuzz nothing.
inline std::string DataFile(const std::string& relative) {
  const std::string path = std::string(THRUSTSCHED_DATA_DIR) + "/" + relative;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::logic_error("fuzz harness: cannot read " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Reads the input's bytes front to back as choices; past the end every
/// choice is 0 (a short input is a small mutation).
class ByteReader {
 public:
  ByteReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}
  bool empty() const { return pos_ >= size_; }
  uint8_t Byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  /// In [0, n) for n >= 1.
  size_t Below(size_t n) { return n <= 256 ? Byte() % n : (Byte() * 256u + Byte()) % n; }
  uint64_t Word() {
    uint64_t w = 0;
    for (int i = 0; i < 8; ++i) w = (w << 8) | Byte();
    return w;
  }
  /// The bytes left, as text (consumes them).
  std::string Rest() {
    std::string s = pos_ < size_
                        ? std::string(reinterpret_cast<const char*>(data_ + pos_), size_ - pos_)
                        : std::string();
    pos_ = size_;
    return s;
  }
  /// Up to `max` bytes as text.
  std::string Chars(size_t max) {
    const size_t n = Below(max + 1);
    std::string s;
    for (size_t i = 0; i < n && !empty(); ++i) s += static_cast<char>(Byte());
    return s;
  }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

}  // namespace thrustsched::fuzz

#endif  // THRUSTSCHED_TESTS_FUZZ_FUZZ_COMMON_H_
