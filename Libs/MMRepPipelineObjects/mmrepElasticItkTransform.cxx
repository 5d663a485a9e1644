// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// mmrep::ElasticTransform as an itk::Transform (see the header).
#include "mmrepElasticItkTransform.h"

namespace mmrep
{
namespace
{
Eigen::Vector3d ToEigen(const itk::Point<double, 3>& p)
{
  return {p[0], p[1], p[2]};
}
} // namespace

void ElasticItkTransform::SetElasticTransforms(std::vector<ElasticTransform> transforms)
{
  transforms_ = std::move(transforms);
  for (auto& t : transforms_)
    t.BuildIndex();
  this->Modified();
}

ElasticItkTransform::OutputPointType ElasticItkTransform::TransformPoint(const InputPointType& point) const
{
  Eigen::Vector3d x = ToEigen(point);
  for (const auto& t : transforms_)
    x = t.Apply(x);
  OutputPointType out;
  for (unsigned a = 0; a < 3; ++a)
    out[a] = x[a];
  return out;
}

Eigen::Matrix3d ElasticItkTransform::Jacobian(const InputPointType& point) const
{
  Eigen::Vector3d x = ToEigen(point);
  Eigen::Matrix3d j = Eigen::Matrix3d::Identity();
  for (const auto& t : transforms_)
  {
    j = t.Jacobian(x) * j; // chain rule: J_{Q∘R}(x) = J_Q(R(x)) J_R(x)
    x = t.Apply(x);
  }
  return j;
}

void ElasticItkTransform::ComputeJacobianWithRespectToPosition(const InputPointType& point,
                                                               JacobianPositionType& jacobian) const
{
  const Eigen::Matrix3d j = Jacobian(point);
  for (unsigned r = 0; r < 3; ++r)
    for (unsigned c = 0; c < 3; ++c)
      jacobian(r, c) = j(r, c);
}

ElasticItkTransform::OutputVectorType ElasticItkTransform::TransformVector(const InputVectorType& vector,
                                                                           const InputPointType& point) const
{
  const Eigen::Vector3d v = Jacobian(point) * Eigen::Vector3d(vector[0], vector[1], vector[2]);
  OutputVectorType out;
  for (unsigned a = 0; a < 3; ++a)
    out[a] = v[a];
  return out;
}

ElasticItkTransform::OutputVnlVectorType ElasticItkTransform::TransformVector(const InputVnlVectorType& vector,
                                                                              const InputPointType& point) const
{
  const Eigen::Vector3d v = Jacobian(point) * Eigen::Vector3d(vector[0], vector[1], vector[2]);
  OutputVnlVectorType out;
  for (unsigned a = 0; a < 3; ++a)
    out[a] = v[a];
  return out;
}

ElasticItkTransform::OutputCovariantVectorType
ElasticItkTransform::TransformCovariantVector(const InputCovariantVectorType& vector, const InputPointType& point) const
{
  // Normals transform with the inverse transpose of the Jacobian.
  const Eigen::Vector3d v = Jacobian(point).inverse().transpose() * Eigen::Vector3d(vector[0], vector[1], vector[2]);
  OutputCovariantVectorType out;
  for (unsigned a = 0; a < 3; ++a)
    out[a] = v[a];
  return out;
}

} // namespace mmrep
