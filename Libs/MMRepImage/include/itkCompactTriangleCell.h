// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// A triangle cell that keeps its three point ids inline, so that millions of them can live in one array.
//
// Why: itk::TriangleCell (ITK 5.2) stores its ids in a std::vector, so every triangle costs two heap
// allocations, which for a CT iso-surface of hundreds of thousands of triangles dominates the filter's run
// (figures: Libs/MMRepImage/README.md).
// A CompactTriangleCell reports itself as a TRIANGLE_CELL and answers every query by delegating to a temporary
// itk::TriangleCell holding the same ids: copies (MakeCopy), boundary features and visitors (Accept) therefore
// see ordinary itk::TriangleCell objects. Only code that dynamic_casts a mesh cell to itk::TriangleCell sees
// the difference.
//
// CompactTriangleCellBlock allocates the cells of a whole mesh in one array; TieCellBlockToContainer ties its
// lifetime to the mesh's cells container (the mesh must use CellsAllocatedAsStaticArray so that it does not delete
// the cells one by one). Cells added later to such a mesh with SetCell are not deleted by it.
#ifndef itkCompactTriangleCell_h
#define itkCompactTriangleCell_h

#include "itkTriangleCell.h"

#include <array>
#include <cstddef>
#include <memory>
#include <new>

namespace itk
{
template <typename TCellInterface> class CompactTriangleCell : public TCellInterface
{
public:
  itkCellCommonTypedefs(CompactTriangleCell);
  itkCellInheritedTypedefs(TCellInterface);
  itkTypeMacro(CompactTriangleCell, CellInterface);

  using TriangleCellType = TriangleCell<TCellInterface>;
  static constexpr unsigned int NumberOfPoints = 3;

  CompactTriangleCell() { m_PointIds.fill(NumericTraits<PointIdentifier>::max()); }
  CompactTriangleCell(PointIdentifier a, PointIdentifier b, PointIdentifier c) : m_PointIds{{a, b, c}} {}
  ~CompactTriangleCell() override = default;
  ITK_DISALLOW_COPY_AND_MOVE(CompactTriangleCell);

  CellGeometryEnum GetType() const override { return CellGeometryEnum::TRIANGLE_CELL; }
  // Copies are ordinary heap-allocated itk::TriangleCell objects.
  void MakeCopy(CellAutoPointer& cellPointer) const override
  {
    auto* copy = new TriangleCellType;
    copy->SetPointIds(m_PointIds.data());
    cellPointer.TakeOwnership(copy);
  }
  unsigned int GetDimension() const override { return 2; }
  unsigned int GetNumberOfPoints() const override { return NumberOfPoints; }
  typename TCellInterface::CellFeatureCount GetNumberOfBoundaryFeatures(int dimension) const override
  {
    return (dimension == 0 || dimension == 1) ? 3 : 0;
  }
  bool GetBoundaryFeature(int dimension, typename TCellInterface::CellFeatureIdentifier id,
                          CellAutoPointer& out) override
  {
    TriangleCellType triangle;
    triangle.SetPointIds(m_PointIds.data());
    return triangle.GetBoundaryFeature(dimension, id, out);
  }
  void SetPointIds(typename TCellInterface::PointIdConstIterator first) override
  {
    std::copy(first, first + NumberOfPoints, m_PointIds.begin());
  }
  void SetPointIds(typename TCellInterface::PointIdConstIterator first,
                   typename TCellInterface::PointIdConstIterator last) override
  {
    std::copy(first, last, m_PointIds.begin());
  }
  void SetPointId(int localId, PointIdentifier id) override { m_PointIds[localId] = id; }
  typename TCellInterface::PointIdIterator PointIdsBegin() override { return m_PointIds.data(); }
  typename TCellInterface::PointIdConstIterator PointIdsBegin() const override { return m_PointIds.data(); }
  typename TCellInterface::PointIdIterator PointIdsEnd() override { return m_PointIds.data() + NumberOfPoints; }
  typename TCellInterface::PointIdConstIterator PointIdsEnd() const override
  {
    return m_PointIds.data() + NumberOfPoints;
  }
  bool EvaluatePosition(CoordRepType* x, PointsContainer* points, CoordRepType* closestPoint, CoordRepType pcoords[],
                        double* dist2, typename TCellInterface::InterpolationWeightType* weights) override
  {
    TriangleCellType triangle;
    triangle.SetPointIds(m_PointIds.data());
    return triangle.EvaluatePosition(x, points, closestPoint, pcoords, dist2, weights);
  }
  // Visitors are handed a temporary itk::TriangleCell (they static_cast the cell to the topology they visit).
  void Accept(typename TCellInterface::CellIdentifier cellId, typename TCellInterface::MultiVisitor* visitor) override
  {
    TriangleCellType triangle;
    triangle.SetPointIds(m_PointIds.data());
    triangle.Accept(cellId, visitor);
  }

private:
  std::array<PointIdentifier, NumberOfPoints> m_PointIds;
};

// Owns the cells of one mesh as a single array. The storage is allocated uninitialised and each cell is
// constructed by Construct(), so that construction (and the first touch of the memory) can run in parallel.
// Every index in [0, size) must be constructed exactly once before the block is destroyed.
template <typename TCellInterface> class CompactTriangleCellBlock
{
public:
  using CellType = CompactTriangleCell<TCellInterface>;
  using PointIdentifier = typename TCellInterface::PointIdentifier;

  explicit CompactTriangleCellBlock(std::size_t size) : m_Size(size), m_Cells(std::allocator<CellType>().allocate(size))
  {
  }
  ~CompactTriangleCellBlock()
  {
    for (std::size_t i = 0; i < m_Size; ++i)
    {
      m_Cells[i].CellType::~CellType(); // qualified: no virtual dispatch
    }
    std::allocator<CellType>().deallocate(m_Cells, m_Size);
  }
  CompactTriangleCellBlock(const CompactTriangleCellBlock&) = delete;
  CompactTriangleCellBlock& operator=(const CompactTriangleCellBlock&) = delete;

  CellType* Construct(std::size_t i, PointIdentifier a, PointIdentifier b, PointIdentifier c)
  {
    return new (m_Cells + i) CellType(a, b, c);
  }

private:
  std::size_t m_Size;
  CellType* m_Cells;
};

// Keeps `block` alive exactly as long as `container` (the mesh's cells container) exists: the block is held by
// an observer of the container, and observers are destroyed with the container.
template <typename TContainer, typename TCellInterface>
void TieCellBlockToContainer(const TContainer* container,
                             std::shared_ptr<CompactTriangleCellBlock<TCellInterface>> block)
{
  container->AddObserver(DeleteEvent(), [block](const EventObject&) {});
}
} // namespace itk

#endif
