// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// File-level reading and writing of FE meshes: format dispatch by extension, VTK readers/writers
// with their error reporting turned into exceptions (VTK prints errors instead of throwing), and
// text writers for the solver formats (mmrepAbaqusWriter.cxx, mmrepFEBioWriter.cxx,
// mmrepGmshWriter.cxx). Writers never leave a partial file behind when they fail.
#include "mmrepFEMeshIO.h"

#include "mmrepCoordinateSpace.h"
#include "mmrepDiskSpace.h"
#include "mmrepFEExport.h"
#include "mmrepResourceBudget.h"
#include "mmrepToolkitMessage.h"

#include <vtkErrorCode.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkUnstructuredGridReader.h>
#include <vtkUnstructuredGridWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <stdexcept>

namespace mmrep
{
namespace
{

std::string Lower(std::string s)
{
  for (auto& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string Extension(const std::string& path)
{
  return Lower(std::filesystem::path(path).extension().string());
}

// While alive, VTK errors and warnings (from objects, and the generic ones the legacy reader
// emits for truncated binary data) are collected instead of printed, so a failure becomes one
// exception line and nothing reaches stderr. VTK's output window and logger are process-wide:
// captures are serialized by a mutex and the previous window and stderr verbosity are restored.
class CapturingOutputWindow : public vtkOutputWindow
{
public:
  static CapturingOutputWindow* New();
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow);
  void DisplayText(const char* text) override
  {
    const auto type = this->GetCurrentMessageType();
    if (first_.empty() && text &&
        (type == MESSAGE_TYPE_ERROR || type == MESSAGE_TYPE_WARNING || type == MESSAGE_TYPE_GENERIC_WARNING))
      first_ = ToolkitMessage(text);
  }
  const std::string& First() const { return first_; }

private:
  std::string first_;
};
vtkStandardNewMacro(CapturingOutputWindow);

class VTKErrors
{
public:
  VTKErrors() : lock_(Mutex())
  {
    previous_ = vtkOutputWindow::GetInstance();
    vtkOutputWindow::SetInstance(window_);
    verbosity_ = vtkLogger::GetCurrentVerbosityCutoff();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  ~VTKErrors()
  {
    vtkLogger::SetStderrVerbosity(verbosity_);
    vtkOutputWindow::SetInstance(previous_);
  }
  VTKErrors(const VTKErrors&) = delete;
  VTKErrors& operator=(const VTKErrors&) = delete;
  bool Any() const { return !window_->First().empty(); }
  const std::string& First() const { return window_->First(); }

private:
  static std::mutex& Mutex()
  {
    static std::mutex mutex;
    return mutex;
  }
  std::lock_guard<std::mutex> lock_;
  vtkSmartPointer<vtkOutputWindow> previous_;
  vtkNew<CapturingOutputWindow> window_;
  vtkLogger::Verbosity verbosity_ = vtkLogger::VERBOSITY_INFO;
};

vtkSmartPointer<vtkUnstructuredGrid> ReadXML(const std::string& path)
{
  VTKErrors errors;
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  if (!reader->CanReadFile(path.c_str()))
    throw std::runtime_error(path + ": not a VTK XML unstructured grid (.vtu) file");
  // Per point: VTK's coordinates and our copy; per cell: connectivity, offsets, types, our element.
  CheckVTKXMLCounts(path, 64, 256);
  reader->SetFileName(path.c_str());
  try
  {
    reader->Update();
  }
  catch (const std::bad_alloc&)
  {
    throw std::runtime_error(path + ": not enough memory to read the mesh it declares");
  }
  if (errors.Any() || reader->GetErrorCode() != 0)
    throw std::runtime_error(path + ": cannot read: " + (errors.Any() ? errors.First() : "read error"));
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> ReadLegacy(const std::string& path, FileSpace& space)
{
  VTKErrors errors;
  vtkNew<vtkUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  if (!reader->IsFileUnstructuredGrid())
    throw std::runtime_error(path + ": not a legacy VTK unstructured grid (.vtk) file");
  reader->ReadAllFieldsOn();
  reader->ReadAllScalarsOn();
  reader->Update();
  if (errors.Any() || reader->GetErrorCode() != 0)
    throw std::runtime_error(path + ": cannot read: " + (errors.Any() ? errors.First() : "read error"));
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  space = SpaceFromHeader(reader->GetHeader());
  return grid;
}

template <class Writer> void WriteVTK(Writer* writer, vtkUnstructuredGrid* grid, const std::string& path)
{
  VTKErrors errors;
  writer->SetFileName(path.c_str());
  writer->SetInputData(grid);
  const int ok = writer->Write();
  if (!ok || errors.Any() || writer->GetErrorCode() != 0)
  {
    // VTK's first report of a failed write is its pipeline's ("returned failure for request"): not a reason.
    const bool full = DiskFull(path) || writer->GetErrorCode() == vtkErrorCode::OutOfDiskSpaceError;
    const std::string first = errors.Any() ? errors.First() : "";
    std::remove(path.c_str());
    if (full || first.empty() || first.find("returned failure for request") != std::string::npos)
      throw std::runtime_error(path + ": cannot write" + (full ? WriteFailureReason(path) : " (is the disk full?)"));
    throw std::runtime_error(path + ": cannot write: " + first);
  }
}

void WriteText(const FEMesh& mesh, const std::string& path, void (*write)(const FEMesh&, std::ostream&))
{
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out)
      throw std::runtime_error(path + ": cannot open for writing");
    write(mesh, out);
    out.flush();
    if (out)
      return;
  }
  const std::string why = WriteFailureReason(path);
  std::remove(path.c_str());
  throw std::runtime_error(path + ": cannot write" + why);
}

} // namespace

std::vector<std::string> ReadableFEMeshExtensions()
{
  return {".vtu", ".vtk"};
}

std::vector<std::string> WritableFEMeshExtensions()
{
  return {".vtu", ".vtk", ".inp", ".feb", ".msh"};
}

FEMesh ReadFEMesh(const std::string& path)
{
  const std::string ext = Extension(path);
  const auto readable = ReadableFEMeshExtensions();
  if (std::find(readable.begin(), readable.end(), ext) == readable.end())
    throw std::runtime_error(path + ": unsupported mesh format '" + ext + "' (readable: .vtu, .vtk)");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw std::runtime_error(path + ": file not found");
  FileSpace space = FileSpace::Untagged;
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  if (ext == ".vtu")
  {
    grid = ReadXML(path);
    space = SpaceFromFieldData(grid);
  }
  else
    grid = ReadLegacy(path, space);
  FEMesh mesh;
  try
  {
    mesh = FromVTK(grid);
  }
  catch (const std::exception& e)
  {
    throw std::runtime_error(path + ": " + e.what());
  }
  if (space == FileSpace::RAS) // written in RAS (older Slicer): our meshes are LPS
  {
    for (auto& x : mesh.nodes)
      x = Point3(-x.x(), -x.y(), x.z());
    for (auto& l : mesh.landmarks)
      l.position = Point3(-l.position.x(), -l.position.y(), l.position.z());
  }
  if (mesh.Empty())
    throw std::runtime_error(path + ": contains no mesh (" + std::to_string(mesh.nodes.size()) + " nodes, " +
                             std::to_string(mesh.elements.size()) + " elements)");
  return mesh;
}

void WriteFEMesh(const FEMesh& mesh, const std::string& path)
{
  WriteFEMesh(mesh, path, Extension(path));
}

void WriteFEMesh(const FEMesh& mesh, const std::string& path, const std::string& format)
{
  std::string f = Lower(format);
  if (!f.empty() && f[0] == '.')
    f.erase(0, 1);
  const auto writable = WritableFEMeshExtensions();
  if (std::find(writable.begin(), writable.end(), "." + f) == writable.end())
    throw std::runtime_error(path + ": unsupported mesh format '" + format +
                             "' (writable: .vtu, .vtk, .inp, .feb, .msh)");
  detail::CheckWritable(mesh, path);
  if (f == "vtu")
  {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff(); // raw binary
    writer->SetHeaderTypeToUInt64();
    writer->SetCompressorTypeToZLib();
    WriteVTK(writer.Get(), ToVTK(mesh), path);
  }
  else if (f == "vtk")
  {
    vtkNew<vtkUnstructuredGridWriter> writer;
    writer->SetFileTypeToBinary();                                               // exact doubles
    writer->SetHeader((std::string("MMRep FE mesh ") + LPSHeaderTag()).c_str()); // Slicer's convention
    WriteVTK(writer.Get(), ToVTK(mesh), path);
  }
  else if (f == "inp")
    WriteText(mesh, path, &detail::WriteAbaqus);
  else if (f == "feb")
    WriteText(mesh, path, &detail::WriteFEBio);
  else
    WriteText(mesh, path, &detail::WriteGmsh);
}

} // namespace mmrep
