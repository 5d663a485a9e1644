// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// The elastic registration R and the lips refinement Q (mmrep::ElasticTransform, applied in the
// order given: {R, Q} is Q∘R) as an itk::Transform<double, 3, 3>, so that ITK pipelines use them as
// any ITK transform: in itk::CompositeTransform, itk::TransformMeshFilter (atlas meshes to the
// speaker) and itk::ResampleImageFilter (which maps output points to input points: Q∘R resamples
// the speaker's CT into atlas space). R and Q are fitted by RegisterAtlas / RefineLocally, not by
// an ITK optimiser, so the transform has no parameters; its Jacobian with respect to position is
// the exact one (chain rule through every step), so vectors and covariant vectors transform too.
#pragma once

#include "mmrepElasticTransform.h"

#include <itkTransform.h>

#include <vector>

namespace mmrep
{

class ElasticItkTransform : public itk::Transform<double, 3, 3>
{
public:
  using Self = ElasticItkTransform;
  using Superclass = itk::Transform<double, 3, 3>;
  using Pointer = itk::SmartPointer<Self>;
  using ConstPointer = itk::SmartPointer<const Self>;
  itkNewMacro(Self);
  itkTypeMacro(ElasticItkTransform, Transform);

  // The maps, applied first to last (indexes are built here if they were not).
  void SetElasticTransforms(std::vector<ElasticTransform> transforms);
  const std::vector<ElasticTransform>& GetElasticTransforms() const { return transforms_; }

  OutputPointType TransformPoint(const InputPointType& point) const override;
  using Superclass::TransformVector;
  OutputVectorType TransformVector(const InputVectorType& vector, const InputPointType& point) const override;
  OutputVnlVectorType TransformVector(const InputVnlVectorType& vector, const InputPointType& point) const override;
  using Superclass::TransformCovariantVector;
  OutputCovariantVectorType TransformCovariantVector(const InputCovariantVectorType& vector,
                                                     const InputPointType& point) const override;
  void ComputeJacobianWithRespectToPosition(const InputPointType& point, JacobianPositionType& jacobian) const override;

  // No parameters (see above).
  void SetParameters(const ParametersType&) override {}
  void SetFixedParameters(const FixedParametersType&) override {}
  void ComputeJacobianWithRespectToParameters(const InputPointType&, JacobianType& jacobian) const override
  {
    jacobian.SetSize(3, 0);
  }

protected:
  ElasticItkTransform() : Superclass(0) {}

private:
  Eigen::Matrix3d Jacobian(const InputPointType& point) const;
  std::vector<ElasticTransform> transforms_;
};

} // namespace mmrep
