// SPDX-License-Identifier: LGPL-2.1-or-later
// Two .geo files that include each other (with a commented-out Include that
// must not count).
// Include "missing.geo";
Include "include_cycle_b.geo";
