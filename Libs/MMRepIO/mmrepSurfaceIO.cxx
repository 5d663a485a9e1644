// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Triangle surfaces through VTK's readers and writers, chosen by file extension.
#include "mmrepSurfaceIO.h"

#include "mmrepCoordinateSpace.h"
#include "mmrepDiskSpace.h"
#include "mmrepIOPath.h"
#include "mmrepResourceBudget.h"
#include "mmrepSurfaceFileChecks.h"
#include "mmrepToolkitMessage.h"

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkErrorCode.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkOBJWriter.h>
#include <vtkPLYReader.h>
#include <vtkPLYWriter.h>
#include <vtkPoints.h>
#include <vtkPolyDataReader.h>
#include <vtkPolyDataWriter.h>
#include <vtkSTLReader.h>
#include <vtkSTLWriter.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtksys/SystemTools.hxx>

#include <cerrno>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace mmrep
{
namespace
{

[[noreturn]] void Fail(const std::string& path, const std::string& what)
{
  throw std::runtime_error("'" + path + "': " + what);
}

// VTK reports problems through ErrorEvent/WarningEvent instead of exceptions; collect the
// first message (and keep it off stderr) so it can go into the thrown error.
class ErrorCollector : public vtkCommand
{
public:
  static ErrorCollector* New() { return new ErrorCollector; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    if (event == vtkCommand::ErrorEvent && message.empty())
    {
      message = ToolkitMessage(data ? static_cast<const char*>(data) : "unknown VTK error");
    }
  }
  std::string message;
};

void Watch(vtkAlgorithm* algorithm, ErrorCollector* collector)
{
  algorithm->AddObserver(vtkCommand::ErrorEvent, collector);
  algorithm->AddObserver(vtkCommand::WarningEvent, collector);
}

std::string SurfaceFormat(const std::string& path)
{
  for (const char* ext : {"vtp", "vtk", "stl", "ply", "obj"})
  {
    if (io::Extension(path) == ext)
    {
      return ext;
    }
  }
  return {};
}

} // namespace

vtkSmartPointer<vtkPolyData> ReadSurface(const std::string& path)
{
  if (!vtksys::SystemTools::FileExists(path, true))
  {
    Fail(path, "surface file does not exist");
  }
  const std::string format = SurfaceFormat(path);
  vtkNew<ErrorCollector> errors;
  vtkSmartPointer<vtkAlgorithm> reader;
  vtkSmartPointer<vtkPolyDataReader> legacy;
  if (format == "vtp")
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (format == "vtk")
  {
    legacy = vtkSmartPointer<vtkPolyDataReader>::New();
    legacy->SetFileName(path.c_str());
    reader = legacy;
  }
  else if (format == "stl")
  {
    auto r = vtkSmartPointer<vtkSTLReader>::New();
    r->SetFileName(path.c_str());
    CheckSTLFile(path);
    r->MergingOn(); // STL repeats the corners of every facet
    reader = r;
  }
  else if (format == "ply")
  {
    CheckPLYFile(path);
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (format == "obj")
  {
    auto r = vtkSmartPointer<vtkOBJReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else
  {
    Fail(path, "unknown surface file extension (supported: .vtp, .vtk, .stl, .ply, .obj)");
  }
  Watch(reader, errors);
  try
  {
    if (format == "vtp")
      CheckVTKXMLCounts(path, 64, 64); // coordinates, normals and our copy; a triangle's ids
    reader->Update();
  }
  catch (const std::bad_alloc&)
  {
    Fail(path, "not enough memory to read the surface it declares");
  }

  if (!errors->message.empty() || reader->GetErrorCode() != vtkErrorCode::NoError)
  {
    const std::string why = !errors->message.empty()
                              ? errors->message
                              : vtkErrorCode::GetStringFromErrorCode(static_cast<int>(reader->GetErrorCode()));
    Fail(path, "cannot read surface: " + why);
  }
  vtkPolyData* output = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (output == nullptr || output->GetNumberOfPoints() == 0)
  {
    Fail(path, "surface file contains no points");
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->DeepCopy(output);
  // Slicer's SPACE tag: legacy header, or field data of .vtp; RAS files are flipped to LPS.
  const FileSpace space = legacy ? SpaceFromHeader(legacy->GetHeader()) : SpaceFromFieldData(surface);
  RemoveSpaceTag(surface);
  if (space == FileSpace::RAS)
  {
    FlipRASToLPS(surface->GetPoints());
  }
  return surface;
}

void WriteSurface(vtkPolyData* surface, const std::string& path)
{
  const std::string format = SurfaceFormat(path);
  if (format.empty())
  {
    Fail(path, "unknown surface file extension (supported: .vtp, .vtk, .stl, .ply, .obj)");
  }
  WriteSurface(surface, path, format);
}

void WriteSurface(vtkPolyData* surface, const std::string& path, const std::string& formatName)
{
  if (surface == nullptr)
  {
    throw std::invalid_argument("WriteSurface: null surface for '" + path + "'");
  }
  std::string format = io::Lower(formatName);
  if (!format.empty() && format[0] == '.')
  {
    format = format.substr(1);
  }
  vtkNew<ErrorCollector> errors;
  vtkSmartPointer<vtkAlgorithm> writer;
  std::function<int()> write;
  if (format == "vtp")
  {
    auto w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->SetInputData(surface);
    w->SetFileName(path.c_str());
    // LZ4: files about as small as zlib's for meshes, compressed several times faster (VTK >= 8 reads it).
    w->SetCompressorTypeToLZ4();
    writer = w;
    write = [w] { return w->Write(); };
  }
  else if (format == "vtk")
  {
    auto w = vtkSmartPointer<vtkPolyDataWriter>::New();
    w->SetInputData(surface);
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary(); // full double precision
    w->SetHeader((std::string("MMRep surface ") + LPSHeaderTag()).c_str());
    writer = w;
    write = [w] { return w->Write(); };
  }
  else if (format == "stl" || format == "ply" || format == "obj")
  {
    // These formats hold triangles/polygons only; triangulate strips and polygons for STL.
    vtkSmartPointer<vtkPolyData> input = surface;
    if (format == "stl")
    {
      vtkNew<vtkTriangleFilter> triangles;
      triangles->SetInputData(surface);
      triangles->PassVertsOff();
      triangles->PassLinesOff();
      triangles->Update();
      input = triangles->GetOutput();
    }
    if (format == "stl")
    {
      auto w = vtkSmartPointer<vtkSTLWriter>::New();
      w->SetFileTypeToBinary();
      w->SetInputData(input);
      w->SetFileName(path.c_str());
      writer = w;
      write = [w] { return w->Write(); };
    }
    else if (format == "ply")
    {
      auto w = vtkSmartPointer<vtkPLYWriter>::New();
      w->SetFileTypeToBinary();
      w->SetInputData(input);
      w->SetFileName(path.c_str());
      writer = w;
      write = [w] { return w->Write(); };
    }
    else
    {
      auto w = vtkSmartPointer<vtkOBJWriter>::New();
      w->SetInputData(input);
      w->SetFileName(path.c_str());
      writer = w;
      write = [w] { return w->Write(); };
    }
  }
  else
  {
    Fail(path, "unknown surface format '" + formatName + "' (supported: vtp, vtk, stl, ply, obj)");
  }
  Watch(writer, errors);
  const int ok = write();
  std::string why;
  const unsigned long code = writer->GetErrorCode();
  const bool failed = !ok || !errors->message.empty() || code != vtkErrorCode::NoError;
  if (failed && (code == vtkErrorCode::OutOfDiskSpaceError || code == ENOSPC || DiskFull(path)))
    why = "no space left on the device";
  else if (failed) // VTK's error code is the errno of its last call (the removal of its partial file): no reason
    why = !errors->message.empty() ? errors->message : std::string("the writer failed") + WriteFailureReason(path);
  else if (format == "ply" ||
           format == "stl") // their writers do not check fwrite: read the file back as a reader would
  {
    try
    {
      format == "ply" ? CheckPLYFile(path) : CheckSTLFile(path);
    }
    catch (const std::exception&)
    {
      why = std::string("the written file is incomplete") + WriteFailureReason(path);
    }
  }
  if (!why.empty())
  {
    vtksys::SystemTools::RemoveFile(path); // never leave a partial file behind
    Fail(path, "cannot write surface: " + why);
  }
}

} // namespace mmrep
