#include "milp/variable.h"

#include <stdexcept>
#include <string>

namespace thrustsched::milp {

std::string_view ToString(VarType type) {
  switch (type) {
    case VarType::kContinuous:
      return "continuous";
    case VarType::kInteger:
      return "integer";
    case VarType::kBinary:
      return "binary";
  }
  return "unknown";
}

Variable VarBlock::operator[](int i) const {
  if (i < 0 || i >= size_) {
    throw std::out_of_range("VarBlock: index " + std::to_string(i) + " outside [0, " +
                            std::to_string(size_) + ")");
  }
  return Variable(start_ + i, model_id_);
}

VarBlock VarBlock::segment(int offset, int size) const {
  if (offset < 0 || size < 0 || offset > size_ || size > size_ - offset) {
    throw std::out_of_range("VarBlock: segment(offset=" + std::to_string(offset) +
                            ", size=" + std::to_string(size) + ") leaves a block of size " +
                            std::to_string(size_));
  }
  return VarBlock(start_ + offset, size, model_id_);
}

std::vector<Variable> VarBlock::ToVector() const {
  std::vector<Variable> vars;
  vars.reserve(static_cast<size_t>(size_));
  for (int i = 0; i < size_; ++i) vars.push_back(Variable(start_ + i, model_id_));
  return vars;
}

std::vector<Variable> Concat(std::initializer_list<VarBlock> blocks) {
  size_t total = 0;
  for (const VarBlock& b : blocks) total += static_cast<size_t>(b.size());
  std::vector<Variable> vars;
  vars.reserve(total);
  for (const VarBlock& b : blocks) {
    for (int i = 0; i < b.size(); ++i) vars.push_back(b[i]);
  }
  return vars;
}

}  // namespace thrustsched::milp
