#include "wld/pvs_edit_list.h"

#include "visibility/file_error.h"
#include "wld/common/read_file.h"

#include <nlohmann/json.hpp>

namespace pvs {

namespace {

constexpr const char* kFormat = "pvscope-pvs-edits";

[[noreturn]] void bad(const std::string& file, const std::string& what) { throw FileError(file, 0, what); }

// Whether doc[key] is the string `value` / the non-negative integer `value`.
bool has_string(const nlohmann::json& doc, const char* key, const char* value)
{
    return doc.contains(key) && doc[key].is_string() && doc[key].get<std::string>() == value;
}
bool has_unsigned(const nlohmann::json& doc, const char* key, uint64_t value)
{
    return doc.contains(key) && doc[key].is_number_unsigned() && doc[key].get<uint64_t>() == value;
}

uint32_t index_field(const nlohmann::json& edit, const char* key, uint32_t limit, const std::string& file,
                     const std::string& where)
{
    if (!edit.contains(key) || !edit[key].is_number_unsigned())
        bad(file, where + ": \"" + key + "\" must be a non-negative integer");
    const uint64_t v = edit[key].get<uint64_t>();
    if (v >= limit)
        bad(file, where + ": \"" + key + "\" " + std::to_string(v) + " out of range (" + std::to_string(limit) + ")");
    return uint32_t(v);
}

bool bool_field(const nlohmann::json& edit, const char* key, bool fallback, const std::string& file,
                const std::string& where)
{
    if (!edit.contains(key))
        return fallback;
    if (!edit[key].is_boolean())
        bad(file, where + ": \"" + key + "\" must be true or false");
    return edit[key].get<bool>();
}

PvsEdit parse_edit(const nlohmann::json& e, const std::string& file, const std::string& where, uint32_t rows,
                   uint32_t regions)
{
    if (!e.is_object() || !e.contains("op") || !e["op"].is_string())
        bad(file, where + ": not an object with an \"op\"");
    const std::string op = e["op"].get<std::string>();
    if (op == "pair") {
        const uint32_t from = index_field(e, "from", rows, file, where);
        const uint32_t to = index_field(e, "to", regions, file, where);
        const bool both = bool_field(e, "both", false, file, where);
        if (both && (to >= rows || from >= regions))
            bad(file, where + ": \"both\" needs a square PVS pair");
        return pair_edit(from, to, bool_field(e, "visible", true, file, where), both);
    }
    if (op == "row") {
        PvsEdit edit;
        edit.op = PvsEdit::Op::Row;
        edit.from = index_field(e, "row", rows, file, where);
        if (!e.contains("visible") || !e["visible"].is_array())
            bad(file, where + ": \"visible\" must be a list of region ids");
        for (size_t k = 0; k < e["visible"].size(); ++k) {
            const nlohmann::json& v = e["visible"][k];
            if (!v.is_number_unsigned() || v.get<uint64_t>() >= regions)
                bad(file, where + ": visible[" + std::to_string(k) + "] is not a region id below " + std::to_string(regions));
            edit.row_visible.push_back(v.get<uint32_t>());
        }
        if (e.contains("note") && e["note"].is_string())
            edit.note = e["note"].get<std::string>();
        return edit;
    }
    bad(file, where + ": unknown op \"" + op + "\" (pair or row)");
}

} // namespace

std::string edit_list_json(const std::vector<PvsEdit>& edits, uint32_t rows, uint32_t regions)
{
    nlohmann::json list = nlohmann::json::array();
    for (const PvsEdit& e : edits) {
        if (e.op == PvsEdit::Op::Pair)
            list.push_back({{"op", "pair"}, {"from", e.from}, {"to", e.to}, {"visible", e.visible}, {"both", e.both}});
        else
            list.push_back({{"op", "row"}, {"row", e.from}, {"visible", e.row_visible}, {"note", e.note}});
    }
    const nlohmann::json doc = {{"format", kFormat}, {"version", 1}, {"rows", rows}, {"regions", regions}, {"edits", list}};
    return doc.dump(2) + "\n";
}

std::vector<PvsEdit> parse_edit_list(const std::string& text, const std::string& file, uint32_t rows, uint32_t regions)
{
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw FileError(file, e.byte > 0 ? e.byte - 1 : 0, std::string("not JSON: ") + e.what());
    } catch (const nlohmann::json::exception& e) { // a number too large for a double ("1e400")
        throw FileError(file, 0, std::string("not JSON: ") + e.what());
    }
    // Field types are checked before any get<>(): nlohmann::json throws type_error for a
    // value of another type, which would escape as something other than FileError.
    if (!doc.is_object() || !has_string(doc, "format", kFormat))
        bad(file, std::string("not a PVS edit list (\"format\": \"") + kFormat + "\" expected)");
    if (!has_unsigned(doc, "version", 1))
        bad(file, "edit list version " + doc.value("version", nlohmann::json(0)).dump() + " (1 expected)");
    if (!has_unsigned(doc, "rows", rows) || !has_unsigned(doc, "regions", regions))
        bad(file, "edit list made for " + doc.value("rows", nlohmann::json(0)).dump() + " rows x " +
                      doc.value("regions", nlohmann::json(0)).dump() + " regions, this zone has " +
                      std::to_string(rows) + " x " + std::to_string(regions) + " (another zone?)");
    if (!doc.contains("edits") || !doc["edits"].is_array())
        bad(file, "\"edits\" must be a list");
    std::vector<PvsEdit> edits;
    for (size_t i = 0; i < doc["edits"].size(); ++i)
        edits.push_back(parse_edit(doc["edits"][i], file, "edit " + std::to_string(i), rows, regions));
    return edits;
}

std::vector<PvsEdit> read_edit_list(const std::string& path, uint32_t rows, uint32_t regions)
{
    const std::vector<uint8_t> bytes = read_whole_file(path);
    return parse_edit_list(std::string(bytes.begin(), bytes.end()), path, rows, regions);
}

} // namespace pvs
