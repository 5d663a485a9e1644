// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
#include "mmrepElasticTransform.h"
#include "mmrepWorkerThreads.h"

#include <itkImageRegionIteratorWithIndex.h>

#include <algorithm>
#include <atomic>
#include <thread>
#include <array>
#include <cmath>
#include <limits>

namespace mmrep
{

double ElasticBump(double t)
{
  const double a = std::abs(t);
  return a >= 1.0 ? 0.0 : (1.0 - a) * (1.0 - a) * (1.0 + 2.0 * a);
}

double ElasticBumpDerivative(double t)
{
  const double a = std::abs(t);
  if (a >= 1.0)
    return 0.0;
  const double d = -6.0 * a * (1.0 - a); // d/da of (1−a)²(1+2a)
  return t < 0 ? -d : d;
}

namespace
{
double GradientNorm(const Eigen::Vector3d& u, const Eigen::Vector3d& h)
{
  const double bx = ElasticBump(u.x()), by = ElasticBump(u.y()), bz = ElasticBump(u.z());
  const Eigen::Vector3d g(ElasticBumpDerivative(u.x()) * by * bz / h.x(),
                          bx * ElasticBumpDerivative(u.y()) * bz / h.y(),
                          bx * by * ElasticBumpDerivative(u.z()) / h.z());
  return g.norm();
}
} // namespace

double MaximumBumpGradient(const Eigen::Vector3d& h)
{
  // |∇φ| is even in each u component, so search [0,1]³: a grid, then a shrinking pattern search
  // from the best grid point (the maximum is smooth and interior in the search variables).
  constexpr int n = 32;
  Eigen::Vector3d best(0.5, 0, 0);
  double bestValue = GradientNorm(best, h);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k)
      {
        const Eigen::Vector3d u(double(i) / n, double(j) / n, double(k) / n);
        const double v = GradientNorm(u, h);
        if (v > bestValue)
        {
          bestValue = v;
          best = u;
        }
      }
  for (double step = 1.0 / n; step > 1e-12; step *= 0.5)
  {
    bool improved = true;
    while (improved)
    {
      improved = false;
      for (int a = 0; a < 3; ++a)
        for (double s : {step, -step})
        {
          Eigen::Vector3d u = best;
          u[a] = std::clamp(u[a] + s, 0.0, 1.0);
          const double v = GradientNorm(u, h);
          if (v > bestValue)
          {
            bestValue = v;
            best = u;
            improved = true;
          }
        }
    }
  }
  return bestValue;
}

double ElasticTransform::Bump(const Eigen::Vector3d& p, const Eigen::Vector3d& node, const Eigen::Vector3d& h,
                              Eigen::Vector3d* gradient)
{
  // Component-wise (p − n)/h: negating p_x and n_x negates t_x exactly, which the symmetry relies on.
  const double tx = (p.x() - node.x()) / h.x();
  const double ty = (p.y() - node.y()) / h.y();
  const double tz = (p.z() - node.z()) / h.z();
  if (std::abs(tx) >= 1.0 || std::abs(ty) >= 1.0 || std::abs(tz) >= 1.0)
  {
    if (gradient)
      gradient->setZero();
    return 0.0;
  }
  const double bx = ElasticBump(tx), by = ElasticBump(ty), bz = ElasticBump(tz);
  if (gradient)
    *gradient =
      Eigen::Vector3d(ElasticBumpDerivative(tx) * by * bz / h.x(), bx * ElasticBumpDerivative(ty) * bz / h.y(),
                      bx * by * ElasticBumpDerivative(tz) / h.z());
  return bx * by * bz;
}

Eigen::Vector3d ElasticTransform::ApplyStep(const ElasticStep& step, const Eigen::Vector3d& h, const Eigen::Vector3d& p,
                                            Eigen::Matrix3d* jacobian)
{
  Eigen::Vector3d g1, g2;
  const double f1 = Bump(p, step.node, h, jacobian ? &g1 : nullptr);
  double f2 = 0;
  Eigen::Vector3d mirrorDelta = step.delta;
  if (step.mirrored)
  {
    const Eigen::Vector3d mirrorNode(-step.node.x(), step.node.y(), step.node.z());
    mirrorDelta.x() = -step.delta.x();
    f2 = Bump(p, mirrorNode, h, jacobian ? &g2 : nullptr);
  }
  if (jacobian)
  {
    Eigen::Matrix3d j = Eigen::Matrix3d::Identity() + step.delta * g1.transpose();
    if (step.mirrored)
      j += mirrorDelta * g2.transpose();
    *jacobian = j * *jacobian;
  }
  if (f1 == 0.0 && f2 == 0.0)
    return p; // untouched, bit for bit
  // Sum the two contributions first (a + b = b + a exactly), then add: mirror-exact.
  Eigen::Vector3d sum;
  for (int a = 0; a < 3; ++a)
    sum[a] = step.delta[a] * f1 + mirrorDelta[a] * f2;
  return p + sum;
}

bool ElasticTransform::HasPreTransform() const
{
  return !(preLinear == Eigen::Matrix3d::Identity() && preTranslation == Eigen::Vector3d::Zero());
}

std::size_t ElasticTransform::StepCount() const
{
  std::size_t n = 0;
  for (const auto& l : levels)
    n += l.steps.size();
  return n;
}

std::vector<std::size_t> ElasticTransform::StepsPerLevel() const
{
  std::vector<std::size_t> n;
  for (const auto& l : levels)
    n.push_back(l.steps.size());
  return n;
}

namespace
{
// Padded cell index along one axis, or INT_MIN when outside the padded range.
inline int CellOf(double p, double boxMin, double h, int cells, int pad)
{
  const double c = std::floor((p - boxMin) / h);
  if (!(c >= -pad && c <= cells - 1 + pad))
    return std::numeric_limits<int>::min();
  return static_cast<int>(c) + pad;
}
} // namespace

void ElasticTransform::BuildIndex()
{
  index_.assign(levels.size(), {});
  for (std::size_t li = 0; li < levels.size(); ++li)
  {
    const auto& level = levels[li];
    auto& idx = index_[li];
    idx.dim = level.cells + 2 * idx.pad;
    const std::size_t d = static_cast<std::size_t>(idx.dim);
    std::vector<std::vector<std::uint32_t>> buckets(d * d * d);
    for (std::size_t s = 0; s < level.steps.size(); ++s)
    {
      const auto& step = level.steps[s];
      std::vector<Eigen::Vector3d> nodes{step.node};
      if (step.mirrored)
        nodes.emplace_back(-step.node.x(), step.node.y(), step.node.z());
      std::vector<std::size_t> cellsTouched;
      for (const auto& n : nodes)
      {
        // Support = cells i−1, i around node i; one more cell each side absorbs rounding.
        std::array<int, 3> lo, hi;
        for (int a = 0; a < 3; ++a)
        {
          const int i = static_cast<int>(std::lround((n[a] - level.boxMin[a]) / level.h[a]));
          lo[a] = std::max(i - 2 + idx.pad, 0);
          hi[a] = std::min(i + 1 + idx.pad, idx.dim - 1);
        }
        for (int x = lo[0]; x <= hi[0]; ++x)
          for (int y = lo[1]; y <= hi[1]; ++y)
            for (int z = lo[2]; z <= hi[2]; ++z)
              cellsTouched.push_back((static_cast<std::size_t>(z) * d + y) * d + x);
      }
      std::sort(cellsTouched.begin(), cellsTouched.end());
      cellsTouched.erase(std::unique(cellsTouched.begin(), cellsTouched.end()), cellsTouched.end());
      for (auto c : cellsTouched)
        buckets[c].push_back(static_cast<std::uint32_t>(s));
    }
    idx.start.assign(d * d * d + 1, 0);
    for (std::size_t c = 0; c < buckets.size(); ++c)
      idx.start[c + 1] = idx.start[c] + static_cast<std::uint32_t>(buckets[c].size());
    idx.steps.reserve(idx.start.back());
    for (const auto& b : buckets)
      idx.steps.insert(idx.steps.end(), b.begin(), b.end());
  }
  indexed_ = true;
}

Eigen::Vector3d ElasticTransform::ApplyInFrame(const Eigen::Vector3d& f, Eigen::Matrix3d* jacobian) const
{
  Eigen::Vector3d p = f;
  for (std::size_t li = 0; li < levels.size(); ++li)
  {
    const auto& level = levels[li];
    if (!indexed_ || index_.size() != levels.size())
    {
      for (const auto& step : level.steps)
        p = ApplyStep(step, level.h, p, jacobian);
      continue;
    }
    // Walk the steps of the point's current cell; when a step moves the point to another cell,
    // continue with that cell's list after the current step. Steps not listed cannot touch it.
    const auto& idx = index_[li];
    const std::size_t d = static_cast<std::size_t>(idx.dim);
    auto cellKey = [&](const Eigen::Vector3d& q) -> long long {
      long long key = 0;
      for (int a = 2; a >= 0; --a)
      {
        const int c = CellOf(q[a], level.boxMin[a], level.h[a], level.cells, idx.pad);
        if (c == std::numeric_limits<int>::min())
          return -1;
        key = key * static_cast<long long>(d) + c;
      }
      return key;
    };
    long long key = cellKey(p);
    std::uint32_t next = 0; // first step index not yet considered
    while (key >= 0)
    {
      const std::uint32_t* begin = idx.steps.data() + idx.start[static_cast<std::size_t>(key)];
      const std::uint32_t* end = idx.steps.data() + idx.start[static_cast<std::size_t>(key) + 1];
      const std::uint32_t* it = std::lower_bound(begin, end, next);
      long long newKey = key;
      for (; it != end; ++it)
      {
        const Eigen::Vector3d q = ApplyStep(level.steps[*it], level.h, p, jacobian);
        next = *it + 1;
        if (q != p)
        {
          p = q;
          newKey = cellKey(p);
          if (newKey != key)
            break;
        }
      }
      if (it == end || newKey == key)
        break;
      key = newKey;
    }
  }
  return p;
}

Eigen::Vector3d ElasticTransform::Apply(const Eigen::Vector3d& x) const
{
  const Eigen::Vector3d y = PreApply(x);
  const Eigen::Vector3d f = ToFrame(y);
  const Eigen::Vector3d g = ApplyInFrame(f);
  if (g == f && !HasPreTransform())
    return x; // outside every support: untouched, bit for bit
  if (g == f)
    return y;
  return ToWorld(g);
}

Eigen::Matrix3d ElasticTransform::Jacobian(const Eigen::Vector3d& x) const
{
  const Eigen::Vector3d y = preLinear * x + preTranslation;
  Eigen::Matrix3d j = Eigen::Matrix3d::Identity();
  ApplyInFrame(ToFrame(y), &j);
  return frameRotation.transpose() * j * frameRotation * preLinear;
}

DisplacementField::Pointer ElasticTransform::ToDisplacementField(const itk::ImageBase<3>* grid) const
{
  auto field = DisplacementField::New();
  field->SetRegions(grid->GetLargestPossibleRegion());
  field->SetOrigin(grid->GetOrigin());
  field->SetSpacing(grid->GetSpacing());
  field->SetDirection(grid->GetDirection());
  field->Allocate();
  FillDisplacementField(field, [this](const Eigen::Vector3d& x) { return Apply(x); });
  return field;
}

void FillDisplacementField(DisplacementField* field, const std::function<Eigen::Vector3d(const Eigen::Vector3d&)>& map)
{
  const auto region = field->GetLargestPossibleRegion();
  const long long slices = static_cast<long long>(region.GetSize(2));
  const unsigned threads = WorkerThreads(8);
  std::atomic<long long> next{0};
  std::vector<std::thread> pool;
  for (unsigned w = 0; w < threads; ++w)
    pool.emplace_back([&] {
      for (long long z = next++; z < slices; z = next++)
      {
        auto slab = region;
        slab.SetIndex(2, region.GetIndex(2) + z);
        slab.SetSize(2, 1);
        for (itk::ImageRegionIteratorWithIndex<DisplacementField> it(field, slab); !it.IsAtEnd(); ++it)
        {
          DisplacementField::PointType pt;
          field->TransformIndexToPhysicalPoint(it.GetIndex(), pt);
          const Eigen::Vector3d x(pt[0], pt[1], pt[2]);
          const Eigen::Vector3d u = map(x) - x;
          DisplacementField::PixelType v;
          for (unsigned a = 0; a < 3; ++a)
            v[a] = static_cast<float>(u[a]);
          it.Set(v);
        }
      }
    });
  for (auto& t : pool)
    t.join();
}

} // namespace mmrep
