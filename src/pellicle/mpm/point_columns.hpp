#pragma once
//! Per-point columns that only some points need, declared by the materials and the transfer
//! that use them (DESIGN.md, "Materials own their state"). A column exists for every point
//! once anyone declares it (zero where its owner has no points), stored as one typed array,
//! so a material's loop indexes it like any other column. Output, snapshots and checkpoints
//! walk the declared columns; they never ask which material owns one.

#include <memory>
#include <stdexcept>
#include <string>
#include <typeindex>
#include <vector>

#include "pellicle/core/types.hpp"

namespace pellicle {

//! What a declared column holds and where it is written.
struct ColumnSpec {
  std::string name;        //!< snapshot array and checkpoint dataset name
  std::string unit;        //!< SI unit, "1" when dimensionless
  bool snapshot = true;    //!< written to the points' .vtu snapshots
  bool checkpoint = true;  //!< written to checkpoints (needed to continue the run)
};

//! A typed reference to a declared column; valid once declared.
template <class T>
struct Column {
  int index = -1;
  bool valid() const { return index >= 0; }
};

//! How a column's values are laid out as doubles (for writers and readers).
enum class ColumnShape { scalar, vector, symmetric, matrix };

namespace detail {
template <class T>
struct ColumnTraits;
template <>
struct ColumnTraits<double> {
  static constexpr ColumnShape shape = ColumnShape::scalar;
  static constexpr int components = 1;
  static double zero() { return 0.0; }
};
template <int Rows, int Cols>
struct ColumnTraits<Eigen::Matrix<double, Rows, Cols>> {
  using Type = Eigen::Matrix<double, Rows, Cols>;
  static constexpr int components = Rows * Cols;
  static Type zero() { return Type::Zero(); }
};
}  // namespace detail

class PointColumns {
 public:
  PointColumns() = default;
  PointColumns(const PointColumns& other) { *this = other; }
  PointColumns& operator=(const PointColumns& other) {
    entries_.clear();
    for (const auto& e : other.entries_)
      entries_.push_back({e.spec, e.shape, e.components, e.type, e.storage->clone()});
    return *this;
  }
  PointColumns(PointColumns&&) noexcept = default;
  PointColumns& operator=(PointColumns&&) noexcept = default;

  //! Declare a column of values of type T (double, or a fixed-size Eigen vector or matrix)
  //! for `points` points, zero-filled. Declaring an existing name again with the same type
  //! returns the same column, so models that share a quantity (the total small strain)
  //! share its column; the same name with another type is a programming error.
  template <class T>
  Column<T> declare(const ColumnSpec& spec, ColumnShape shape, long points) {
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      if (entries_[i].spec.name != spec.name) continue;
      if (entries_[i].type != std::type_index(typeid(T)))
        throw std::logic_error("point column '" + spec.name + "' declared with two types");
      return {static_cast<int>(i)};
    }
    auto storage = std::make_unique<Typed<T>>();
    storage->values.assign(points, detail::ColumnTraits<T>::zero());
    entries_.push_back({spec, shape, detail::ColumnTraits<T>::components,
                        std::type_index(typeid(T)), std::move(storage)});
    return {static_cast<int>(entries_.size()) - 1};
  }

  //! The column of that name and type, or an invalid one.
  template <class T>
  Column<T> find(const std::string& name) const {
    for (std::size_t i = 0; i < entries_.size(); ++i)
      if (entries_[i].spec.name == name && entries_[i].type == std::type_index(typeid(T)))
        return {static_cast<int>(i)};
    return {};
  }

  template <class T>
  std::vector<T>& operator[](Column<T> c) {
    return static_cast<Typed<T>&>(*entries_[c.index].storage).values;
  }
  template <class T>
  const std::vector<T>& operator[](Column<T> c) const {
    return static_cast<const Typed<T>&>(*entries_[c.index].storage).values;
  }

  int count() const { return static_cast<int>(entries_.size()); }
  const ColumnSpec& spec(int i) const { return entries_[i].spec; }
  ColumnShape shape(int i) const { return entries_[i].shape; }
  //! Doubles per point of column i.
  int components(int i) const { return entries_[i].components; }
  //! Column i as `points × components` contiguous doubles (writers and checkpoint readers).
  double* data(int i) { return entries_[i].storage->data(); }
  const double* data(int i) const { return entries_[i].storage->data(); }

  //! Grow (zero-filled) or shrink every column to `points` points.
  void resize(long points) {
    for (auto& e : entries_) e.storage->resize(points);
  }
  void reserve(long points) {
    for (auto& e : entries_) e.storage->reserve(points);
  }
  //! Bytes held per point by the declared columns.
  std::size_t bytes_per_point() const {
    std::size_t bytes = 0;
    for (const auto& e : entries_) bytes += e.components * sizeof(double);
    return bytes;
  }

 private:
  struct Storage {
    virtual ~Storage() = default;
    virtual void resize(long points) = 0;
    virtual void reserve(long points) = 0;
    virtual double* data() = 0;
    virtual std::unique_ptr<Storage> clone() const = 0;
  };
  template <class T>
  struct Typed final : Storage {
    static_assert(sizeof(T) == detail::ColumnTraits<T>::components * sizeof(double),
                  "a column type must be a packed array of doubles");
    std::vector<T> values;
    void resize(long points) override { values.resize(points, detail::ColumnTraits<T>::zero()); }
    void reserve(long points) override { values.reserve(points); }
    double* data() override { return reinterpret_cast<double*>(values.data()); }
    std::unique_ptr<Storage> clone() const override { return std::make_unique<Typed>(*this); }
  };
  struct Entry {
    ColumnSpec spec;
    ColumnShape shape;
    int components;
    std::type_index type;
    std::unique_ptr<Storage> storage;
  };
  std::vector<Entry> entries_;
};

}  // namespace pellicle
