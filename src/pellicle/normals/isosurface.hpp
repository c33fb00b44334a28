#pragma once
//! The local isosurface method of Sulsky & York (2000): in each grid cell, nodal values χ of a
//! B-spline interpolant are found in the least-squares sense so that χ = 1 at the cell's
//! membrane points and χ = 0 at one extra point placed at random in the cell (eqs 10, 13);
//! the normal at a point is ∇χ there (eqs 11, 16).
//!   linear:    bilinear/trilinear χ on the cell's 4 / 8 nodes (§3–4);
//!   quadratic: quadratic B-splines centred on the 9 / 27 surrounding cell centres (§5–6);
//!   hybrid:    the paper's §8 rule: quadratic when the cell holds enough points (2D: 7,
//!              3D: 26), linear when it holds a few (2D: 3–6, 3D: 7–25), and cells with fewer
//!              — or whose points only graze the cell, too narrow to fix a normal — joined
//!              with neighbours into 2×2 (2×2×2), 3×3 … blocks with linear χ until enough;
//!   offset:    the hybrid rule with 2^(D−1) extra points half a cell to one side of the
//!              points instead of one random point (not in the paper; see isosurface.cpp);
//!   chi2:      the hybrid rule with a second extra point, χ = 2, across the points from the
//!              χ = 0 one (the paper's §8 experiment);
//!   guarded:   the hybrid rule, the normal turned towards the neighbours' principal
//!              direction where χ has too little slope across the points to trust ∇χ.
//! Every fit also sees the points' mirror images beyond the symmetry planes or walls the
//! membrane ends on (mirror_images.hpp). Each small system is solved by a rank-revealing QR
//! (minimum-norm when underdetermined), not the normal equations; when its condition number is too
//! large the extra point is moved (up to 8 tries; §4). Where ∇χ vanishes the cell's points fall
//! back to principal components. Normals are unsigned (the method cannot tell sides); see
//! complete_frames.

#include <memory>
#include <vector>

#include "pellicle/normals/frame_estimator.hpp"

namespace pellicle {

//! `mass_matrix` is the linear construction solved through the normal equations
//! T χ = Sᵀ χ⁰, T = SᵀS (thesis §7.4, the paper's eq 13), kept to compare with the QR solve.
enum class IsosurfaceBasis { linear, quadratic, hybrid, mass_matrix };

//! Diagnostics of the last estimate (for `pellicle normals` and the tests).
struct IsosurfaceStatistics {
  std::vector<double> condition;  //!< per solved system: cond(A)² = cond of the normal equations
  long fallbacks = 0;             //!< points whose ∇χ vanished
  //! Per point: |∇χ| × the distance from the χ = 0 point to the fitted points, about 1 where χ
  //! falls cleanly across them, near 0 where χ is about 1 at its maximum there.
  std::vector<double> slope;
  long guarded = 0;  //!< guarded variant: points whose normal took in the principal direction
};

//! Variants of the construction (isosurface.cpp).
struct IsosurfaceOptions {
  //! Instead of the paper's one random point, 2^(D−1) points with χ = 0 placed half a cell to
  //! one side of the cell's points.
  bool offset = false;
  //! A second extra point, χ = 2, across the points from the random χ = 0 one (paper §8).
  bool chi_two = false;
  //! Where |∇χ| × reach (IsosurfaceStatistics::slope) is below 0.8, blend the normal towards
  //! the neighbours' direction of least spread (principal_directions.hpp), fully below 0.2.
  bool guarded = false;
};

template <int D>
class IsosurfaceEstimator final : public FrameEstimator<D> {
 public:
  IsosurfaceEstimator(const FrameSetup<D>& setup, IsosurfaceBasis basis,
                      IsosurfaceOptions options = {})
      : setup_(setup),
        basis_(basis),
        offset_(options.offset),
        chi_two_(options.chi_two),
        guarded_(options.guarded) {}
  void estimate(const std::vector<Vec<D>>& position, long begin, long end,
                std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent) override;
  int reach() const override;
  unsigned planes_touched(const std::vector<Vec<D>>& position, long begin, long end) const override;
  bool estimate_part(const BodyPart& part, const std::vector<Vec<D>>& position,
                     std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent) override;

  //! Raw unit gradients ∇χ/|∇χ| of points [begin, end), no orientation (the paper's output).
  void gradients(const std::vector<Vec<D>>& position, long begin, long end,
                 std::vector<Vec<D>>& normal) {
    gradients(position, begin, end, normal, {});
  }
  const IsosurfaceStatistics& statistics() const { return statistics_; }
  //! Smallest point counts for the quadratic and the unjoined linear construction (hybrid).
  static constexpr int quadratic_threshold = D == 2 ? 7 : 26;
  static constexpr int linear_threshold = D == 2 ? 3 : 7;

 private:
  FrameSetup<D> setup_;
  IsosurfaceBasis basis_;
  bool offset_;
  bool chi_two_;
  bool guarded_;
  IsosurfaceStatistics statistics_;
  //! The same, where [begin, end) also holds the mirror images in `planes` (grid lines) of the
  //! points near them: a single cell with a face on such a plane fits its points together with
  //! their images, which lie in the cell beyond it.
  void gradients(const std::vector<Vec<D>>& position, long begin, long end,
                 std::vector<Vec<D>>& normal, const std::vector<MirrorPlane>& planes);
  //! estimate, with the planes the body ends on given.
  void frames(const std::vector<Vec<D>>& position, long begin, long end,
              std::vector<Vec<D>>& normal, std::vector<Vec<D>>& tangent,
              const std::vector<MirrorPlane>& ended_on);
};

template <int D>
std::unique_ptr<FrameEstimator<D>> make_isosurface_linear(const FrameSetup<D>& setup);
template <int D>
std::unique_ptr<FrameEstimator<D>> make_isosurface_quadratic(const FrameSetup<D>& setup);
template <int D>
std::unique_ptr<FrameEstimator<D>> make_isosurface_hybrid(const FrameSetup<D>& setup);
template <int D>
std::unique_ptr<FrameEstimator<D>> make_mass_matrix(const FrameSetup<D>& setup);
//! The hybrid rule with the offset extra points instead of the random one.
template <int D>
std::unique_ptr<FrameEstimator<D>> make_isosurface_offset(const FrameSetup<D>& setup);
//! The hybrid rule with a second extra point, χ = 2, on the far side (paper §8).
template <int D>
std::unique_ptr<FrameEstimator<D>> make_isosurface_chi_two(const FrameSetup<D>& setup);
//! The hybrid rule, with principal directions where χ has no slope across the points.
template <int D>
std::unique_ptr<FrameEstimator<D>> make_isosurface_guarded(const FrameSetup<D>& setup);

extern template class IsosurfaceEstimator<2>;
extern template class IsosurfaceEstimator<3>;

}  // namespace pellicle
