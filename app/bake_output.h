// What `bake` writes: the PVS into a copy of the input in its own format (or, for a Doom map with
// --in-place, into its GL file with a backup), a PVS edit list applied first, and the portals the
// bake used as a portal file. Messages go to `err`; a file that cannot be written throws FileError.
#pragma once

#include "app/bake_input.h"
#include "app/bake_options.h"
#include "visibility/methods/portal_input.h"
#include "visibility/pvs.h"

#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace pvs::app {

// The PVS into options.output in the input's format (pvs_writeback.h; a Doom map: GL_PVS, and
// REJECT with --reject). An S3D whose drawing was dropped is read again for the write. Returns
// what the writer reports of the file (PvsWriteback::fields).
std::vector<ReportField> write_bake_output(const BakeOptions& options, const BakeInput& in, const Pvs& pvs,
                                           std::FILE* err);

// --apply-edits: the list applied to the PVS in place, before anything is written or reported.
// Returns the number of edits, 0 without a list.
size_t apply_edit_list(const BakeOptions& options, Pvs& pvs, std::FILE* err);

// --write-prt: PRT1 of the portals used, or PRT2 (cluster portals and the cluster map) when the
// bake ran over clusters.
void write_portal_file(const std::string& path, const Zone& zone, const PortalInput& portals, std::FILE* err);

} // namespace pvs::app
