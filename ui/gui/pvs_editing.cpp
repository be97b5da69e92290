// InspectorState's PVS editing (inspector_state.h, "PVS editing"): an EditablePvs over the
// active PVS, published as PvsSource::Edited after every change.
#include "ui/gui/inspector_state.h"

#include "visibility/file_error.h"
#include "visibility/methods/vis_method.h"
#include "wld/pvs_edit_list.h"
#include "wld/pvs_writeback.h"

#include <stdexcept>

namespace pvs::gui {

void InspectorState::publish_edits()
{
    edited_pvs_ = editor_->to_pvs();
    pvs_source_ = PvsSource::Edited;
    rebuild_culler();
}

bool InspectorState::edit_pvs(const PvsEdit& edit)
{
    if (!zone_)
        return false;
    if (!editor_) {
        const Pvs* base = active_pvs();
        if (!base)
            return false;
        editor_.emplace(*base);
    }
    try {
        editor_->apply(edit);
    } catch (const std::invalid_argument& e) {
        error_ = e.what();
        return false;
    }
    publish_edits();
    return true;
}

bool InspectorState::fill_pvs_row(uint32_t row, const std::string& method)
{
    if (!zone_)
        return false;
    if (method == "cleared")
        return edit_pvs(cleared_row_edit(row));
    const VisMethod* m = find_vis_method(method);
    if (!m || !m->bakes) {
        error_ = "no method '" + method + "' to fill a row from";
        return false;
    }
    try {
        MethodSettings settings;
        MethodRun run = m->run(*zone_, settings);
        if (!run.pvs || row >= run.pvs->row_count())
            return false;
        return edit_pvs(row_edit_from(*run.pvs, row, method));
    } catch (const std::exception& e) { // a method that cannot run on this zone
        error_ = e.what();
        return false;
    }
}

bool InspectorState::undo_pvs_edit()
{
    if (!editor_ || !editor_->can_undo())
        return false;
    editor_->undo();
    publish_edits();
    return true;
}

bool InspectorState::redo_pvs_edit()
{
    if (!editor_ || !editor_->can_redo())
        return false;
    editor_->redo();
    publish_edits();
    return true;
}

std::string InspectorState::pvs_edit_list_json() const
{
    if (!editor_)
        return {};
    return edit_list_json(editor_->edits(), editor_->row_count(), editor_->region_count());
}

bool InspectorState::load_pvs_edit_list(const std::string& path)
{
    const Pvs* base = editor_ ? nullptr : active_pvs();
    if (!zone_ || (!editor_ && !base))
        return false;
    const uint32_t rows = editor_ ? editor_->row_count() : base->row_count();
    const uint32_t regions = editor_ ? editor_->region_count() : base->region_count();
    try {
        const std::vector<PvsEdit> edits = read_edit_list(path, rows, regions);
        for (const PvsEdit& edit : edits)
            if (!edit_pvs(edit))
                return false;
        return true;
    } catch (const FileError& e) {
        error_ = e.what();
        return false;
    }
}

bool InspectorState::save_pvs(const std::string& out_path, std::string& message)
{
    const Pvs* pvs = active_pvs();
    if (!zone_ || !pvs) {
        error_ = "no PVS to save (choose a PVS source)";
        return false;
    }
    try {
        message = write_pvs_in_zone_format(*zone_, zone_load_, *pvs, out_path).summary;
        return true;
    } catch (const std::exception& e) { // FileError, or invalid_argument from a writer
        error_ = e.what();
        return false;
    }
}

size_t InspectorState::pvs_edit_popping_risk(const Pvs& reference) const
{
    return editor_ ? editor_->popping_risk(reference) : 0;
}

} // namespace pvs::gui
