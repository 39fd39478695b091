// Variable handles and variable types of the generic MILP builder.
//
// A `Variable` is a cheap value type naming one column of a `Model`; a
// `VarBlock` names a contiguous range of columns (for example the state x_k or
// the thruster binaries u_k of one grid interval). Both remember which model
// created them, so a constraint that mixes variables of two models is rejected.
//
//   milp::Model model("demo");
//   milp::Variable x = model.AddContinuous(0.0, 10.0, "x");
//   milp::VarBlock u = model.AddVariables(4, 0.0, 1.0, milp::VarType::kBinary, "u");
//   model.AddConstraint(x + 2.0 * u[0] <= 3.0, "cap");
#ifndef THRUSTSCHED_MILP_VARIABLE_H_
#define THRUSTSCHED_MILP_VARIABLE_H_

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string_view>
#include <vector>

namespace thrustsched::milp {

/// +infinity for bounds. Writers turn it into MPS `PL`/`MI`/`FR`.
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

enum class VarType { kContinuous, kInteger, kBinary };
std::string_view ToString(VarType type);

/// Handle to one column of a Model. Pass by value.
class Variable {
 public:
  Variable() = default;  // invalid handle (index -1); usable only as a placeholder
  int index() const { return index_; }
  std::uint32_t model_id() const { return model_id_; }
  bool is_valid() const { return index_ >= 0; }
  friend bool operator==(Variable a, Variable b) {
    return a.index_ == b.index_ && a.model_id_ == b.model_id_;
  }
  friend bool operator!=(Variable a, Variable b) { return !(a == b); }

 private:
  friend class Model;
  friend class VarBlock;
  Variable(int index, std::uint32_t model_id) : index_(index), model_id_(model_id) {}
  int index_ = -1;
  std::uint32_t model_id_ = 0;
};

/// Contiguous columns [start, start + size) of one Model.
class VarBlock {
 public:
  VarBlock() = default;
  int start() const { return start_; }
  int size() const { return size_; }
  std::uint32_t model_id() const { return model_id_; }
  /// @throws std::out_of_range if i is not in [0, size).
  Variable operator[](int i) const;
  /// @throws std::out_of_range if the segment leaves the block.
  VarBlock segment(int offset, int size) const;
  /// The handles of the block, in column order (for Model::AddRows).
  std::vector<Variable> ToVector() const;

 private:
  friend class Model;
  VarBlock(int start, int size, std::uint32_t model_id)
      : start_(start), size_(size), model_id_(model_id) {}
  int start_ = 0;
  int size_ = 0;
  std::uint32_t model_id_ = 0;
};

/// Handles of several blocks, concatenated in order (e.g. {x_k, u_k, x_k1}).
std::vector<Variable> Concat(std::initializer_list<VarBlock> blocks);

}  // namespace thrustsched::milp

#endif  // THRUSTSCHED_MILP_VARIABLE_H_
