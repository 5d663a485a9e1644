// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// MeshConvert: FE face model from .vtu/.vtk to .vtu, .vtk, .inp, .feb or .msh (by extension).
#include "mmrepCLI.h"
#include "mmrepFEMeshIO.h"
#include "mmrepHalfModel.h"

#include <algorithm>

extern const char MeshConvertXML[];

MMREP_MODULE_ENTRY_POINT(int argc, char* argv[])
{
  return mmrep::cli::RunModule(argc, argv, MeshConvertXML, [](mmrep::cli::ModuleContext& ctx) {
    const std::string input = ctx.args.String("inputMesh");
    const std::string output = ctx.args.String("outputMesh");
    // Check the output format before doing any work.
    const std::string extension = mmrep::cli::FileExtension(output);
    const auto writable = mmrep::WritableFEMeshExtensions();
    if (std::find(writable.begin(), writable.end(), extension) == writable.end())
      throw mmrep::cli::ModuleError("outputMesh " + output + ": unsupported extension '" + extension +
                                    "' (use .vtu, .vtk, .inp, .feb or .msh)");

    ctx.progress.Start("Converting FE mesh");
    mmrep::FEMesh mesh;
    try
    {
      mesh = mmrep::ReadFEMesh(input);
    }
    catch (const std::exception& e)
    {
      throw mmrep::cli::ModuleError(std::string("inputMesh ") + e.what());
    }
    if (ctx.args.Bool("half"))
    {
      try
      {
        mesh = mmrep::LeftHalfModel(mesh);
      }
      catch (const std::exception& e)
      {
        throw mmrep::cli::ModuleError("inputMesh " + input + ": no half model: " + e.what());
      }
    }
    ctx.progress.Report(0.5);

    mmrep::cli::AtomicOutput out(output);
    try
    {
      // The temporary name keeps the extension, but the format is named explicitly anyway.
      mmrep::WriteFEMesh(mesh, out.TempPath(), extension.substr(1));
    }
    catch (const std::exception& e)
    {
      throw mmrep::cli::ModuleError(std::string("outputMesh ") + e.what());
    }
    ctx.progress.Report(0.95);
    out.Commit();
    ctx.progress.End();
  });
}
