// cvtmesh: the library's public API in one include — read a mesh or model, optimize it, write
// it, and measure its quality.
//
//   #include <cvtmesh/cvtmesh.h>
//   cvtmesh::MeshData d = cvtmesh::read_mesh("model.geo");      // .geo, .msh, .stl, .mesh, ...
//   cvtmesh::OptimizeResult r = cvtmesh::optimize(d, {});       // the dimension's default method
//   cvtmesh::write_mesh(d, "out.msh");                           // format by extension
//   cvtmesh::QualityStats s = cvtmesh::quality_stats(d.tet, "optimized");
//
// Installed as <prefix>/include/cvtmesh/cvtmesh.h beside the library's own headers
// (<prefix>/include/cvtmesh/core/...), which it includes as "core/...": the package's include
// path (find_package(cvtmesh), pkg-config cvtmesh) holds both <prefix>/include and
// <prefix>/include/cvtmesh. Errors: cvtmesh::InputError (bad input), OutputError (cannot
// write), InvariantError (internal), all std::runtime_error.
#pragma once

#include "core/io/read_mesh.h"
#include "core/io/write_mesh.h"
#include "core/pipeline/method_registry.h"
#include "core/pipeline/optimize.h"
#include "core/pipeline/option_schema.h"
#include "core/quality/quality_fields.h"
#include "core/quality/quality_stats.h"
#include "core/quality/quality_table.h"
#include "core/util/error.h"
