// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026 MMRep developers (see LICENSE)
// Surface files checked before VTK reads them. vtkPLYReader reads past the end of a truncated file
// (a crash), allocates whatever count a header claims (minutes and gigabytes), and takes faces
// whose vertex indices do not exist; vtkSTLReader takes a binary STL cut short. Each check walks
// the file as the format defines it and throws std::runtime_error("'<path>': ...") naming the
// defect, so that VTK only ever sees files that hold what their headers say.
#pragma once

#include <string>

namespace mmrep
{

// PLY (ascii, binary_little_endian, binary_big_endian): a header with vertex x, y, z, faces (if
// any) with a vertex_indices list, and an end_header; every element's data present (counts checked against the file's length before
// anything is walked); list counts within 0..1000; face vertex indices within the vertex count.
void CheckPLYFile(const std::string& path);

// STL: binary (80-byte header, triangle count, 50 bytes a triangle: the length must match) or
// ASCII ("solid" ... "endsolid").
void CheckSTLFile(const std::string& path);

} // namespace mmrep
