#!/bin/sh
# SPDX-License-Identifier: LGPL-2.1-or-later
# The compiler launcher CMakeLists.txt sets where ccache is installed:
#   ccache-launcher.sh CCACHE SOURCE_DIR COMPILER ARGS...
# CCACHE_BASEDIR: paths below the clone's folder are hashed as relative ones,
# so that clones and worktrees in other folders share the cache.
# CCACHE_NOHASHDIR: the working directory is not hashed into Debug builds
# (-g) either. CCACHE_SLOPPINESS: what GCC's precompiled headers need
# (ccache's manual, "Precompiled headers"). A user's own setting wins.
ccache=$1
source_dir=$2
shift 2
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$source_dir}"
export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}"
# Making a precompiled header: remove the old one first. CMake compiles it
# with `-include <header>`, and ccache hashes a .gch it finds beside that
# header as one in use: a stale one would store the new header under a key
# that no fresh build folder computes, so that every clone missed the cache
# for the files that use it (doc/build.md).
previous=
for argument in "$@"; do
  if [ "$previous" = "-o" ]; then
    case "$argument" in
      *.gch) rm -f "$argument" ;;
    esac
  fi
  previous=$argument
done
exec "$ccache" "$@"
