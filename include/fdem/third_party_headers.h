// SPDX-License-Identifier: LGPL-2.1-or-later
// The third-party headers that nearly every translation unit of the library
// and its tests reads (most reach them through fdem/model.h and
// fdem/blocks/elastic_block.h). CMakeLists.txt precompiles them once per
// target (FDEM_PRECOMPILED_HEADERS): parsing deal.II's and Trilinos's
// headers was most of each file's compile time (doc/build.md). Only
// headers from outside the project belong here, so that editing a project
// header never rebuilds the precompiled one.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>
