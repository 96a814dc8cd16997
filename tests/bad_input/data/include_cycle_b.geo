// SPDX-License-Identifier: LGPL-2.1-or-later
/* The other half of the cycle, through a path with "..": */
Include "../data/include_cycle_a.geo";
