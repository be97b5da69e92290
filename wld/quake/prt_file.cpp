#include "wld/quake/prt_file.h"

#include "visibility/file_error.h"
#include "wld/common/quote.h"
#include "wld/common/read_file.h"

#include <algorithm>
#include <cassert>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <stdexcept>
#include <system_error>

namespace pvs::quake {

namespace {

// The shortest text one portal can take: "3 0 0(0 0 0)(0 0 0)(0 0 0)". Used only to cap
// reservations, so a declared count never allocates more than the text could hold.
constexpr size_t kMinPortalBytes = 26;
constexpr size_t kMinPointBytes = 7; // "(0 0 0)"
constexpr int64_t kMaxCount = std::numeric_limits<int32_t>::max(); // region ids are int32_t

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }
bool ends_token(char c) { return is_space(c) || c == '(' || c == ')'; }

std::string quoted(std::string_view token) { return quote_for_message(token, 24); }

bool is_binary(std::string_view token)
{
    return std::any_of(token.begin(), token.end(), [](char c) {
        const auto u = static_cast<unsigned char>(c);
        return u < 0x20 || u >= 0x7F;
    });
}

enum class NumberStatus { Ok, Invalid, OutOfRange };

// from_chars does not take a leading '+', which C's scanf (and so id/ericw vis) accepts.
std::string_view strip_plus(std::string_view token)
{
    if (token.size() >= 2 && token[0] == '+' && token[1] != '-' && token[1] != '+')
        token.remove_prefix(1);
    return token;
}

NumberStatus parse_integer(std::string_view token, int64_t& value)
{
    token = strip_plus(token);
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, value);
    if (ec == std::errc::result_out_of_range)
        return NumberStatus::OutOfRange;
    if (ec != std::errc() || ptr != end)
        return NumberStatus::Invalid;
    return NumberStatus::Ok;
}

// Correctly rounded to float. A value below the float range (ericw prints doubles) becomes 0 or a
// subnormal; one above it is out of range; inf and nan are left to the caller to refuse.
NumberStatus parse_float(std::string_view token, float& value)
{
    token = strip_plus(token);
    const char* end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, value);
    if (ec != std::errc::result_out_of_range)
        return ec == std::errc() && ptr == end ? NumberStatus::Ok : NumberStatus::Invalid;
    double wide = 0.0;
    const auto [wide_ptr, wide_ec] = std::from_chars(token.data(), end, wide);
    if (wide_ec != std::errc() || wide_ptr != end || !(std::fabs(wide) <= static_cast<double>(FLT_MAX)))
        return NumberStatus::OutOfRange;
    value = static_cast<float>(wide);
    return NumberStatus::Ok;
}

class PrtParser {
public:
    PrtParser(std::string_view text, const std::string& file) : text_(text), file_(file) {}

    PrtFile parse()
    {
        PrtFile prt;
        prt.version = read_magic();
        int64_t leaf_count = 0, cluster_count = 0, portal_count = 0;
        size_t cluster_count_at = 0;
        if (prt.version == PrtVersion::Prt1) {
            leaf_count = read_count("leaf count");
            portal_count = read_count("portal count");
        } else if (prt.version == PrtVersion::Prt2) {
            leaf_count = read_count("leaf count");
            cluster_count = read_count("cluster count", &cluster_count_at);
            portal_count = read_count("portal count");
        } else {
            cluster_count = read_count("cluster count", &cluster_count_at);
            portal_count = read_count("portal count");
            leaf_count = read_count("leaf count");
        }
        // A cluster holds at least one leaf. More clusters than leaves would only make a bake
        // over them cost cluster_count^2 bits for nothing.
        if (cluster_count > leaf_count)
            fail(cluster_count_at, "the header declares " + std::to_string(cluster_count) + " clusters for " +
                                       std::to_string(leaf_count) + " leaves; a cluster holds at least one leaf");
        prt.leaf_count = static_cast<uint32_t>(leaf_count);
        prt.cluster_count = static_cast<uint32_t>(cluster_count);

        const size_t remaining = text_.size() - pos_;
        const size_t portals_to_reserve = std::min(static_cast<size_t>(portal_count), remaining / kMinPortalBytes);
        prt.portals.portals.reserve(portals_to_reserve);
        prt.portals.points.reserve(std::min(portals_to_reserve * 4, remaining / kMinPointBytes));

        for (int64_t i = 0; i < portal_count; ++i)
            read_portal(prt, i, portal_count);
        if (prt.version == PrtVersion::Prt2)
            read_cluster_lines(prt);
        else if (prt.version == PrtVersion::Prt1Am)
            read_leaf_clusters(prt);

        skip_space();
        if (pos_ < text_.size()) {
            const size_t start = pos_;
            const std::string_view token = any_token();
            int64_t ignored = 0;
            std::string reason = "unexpected " + quoted(token) + " after the last of " +
                                 (prt.has_clusters() ? "the cluster map" : std::to_string(portal_count) + " portals") +
                                 "; only whitespace may follow";
            if (!prt.has_clusters() && parse_integer(token, ignored) == NumberStatus::Ok)
                reason += " (a Quake 3 portal file has a face count and face lines here; only Quake 1's PRT1, PRT2 "
                          "and PRT1-AM are supported)";
            fail(start, reason);
        }
        return prt;
    }

private:
    [[noreturn]] void fail(size_t offset, const std::string& reason) const
    {
        const size_t clamped = std::min(offset, text_.size());
        const auto newlines = std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(clamped), '\n');
        throw FileError(file_, clamped, "line " + std::to_string(newlines + 1) + ": " + reason);
    }

    void skip_space()
    {
        while (pos_ < text_.size() && is_space(text_[pos_]))
            ++pos_;
    }

    // The next number-like token (up to whitespace or a parenthesis); empty when the text ends or
    // the next character is a parenthesis. Call after skip_space.
    std::string_view number_token()
    {
        const size_t start = pos_;
        while (pos_ < text_.size() && !ends_token(text_[pos_]))
            ++pos_;
        return text_.substr(start, pos_ - start);
    }

    // A token for a message: the number-like run, or the single parenthesis found instead.
    std::string_view any_token()
    {
        std::string_view token = number_token();
        if (token.empty() && pos_ < text_.size())
            token = text_.substr(pos_, 1);
        return token;
    }

    PrtVersion read_magic()
    {
        skip_space();
        if (pos_ == text_.size())
            fail(pos_, "empty file: expected a PRT1, PRT2 or PRT1-AM header");
        const size_t start = pos_;
        while (pos_ < text_.size() && !is_space(text_[pos_]))
            ++pos_;
        const std::string_view magic = text_.substr(start, pos_ - start);
        if (magic == "PRT1")
            return PrtVersion::Prt1;
        if (magic == "PRT2")
            return PrtVersion::Prt2;
        if (magic == "PRT1-AM")
            return PrtVersion::Prt1Am;
        if (is_binary(magic))
            fail(start, "not a portal file: expected a PRT1, PRT2 or PRT1-AM header, found binary data " + quoted(magic));
        if (magic.starts_with("PRT"))
            fail(start, "unknown portal file version " + quoted(magic) + "; PRT1, PRT2 and PRT1-AM are supported");
        fail(start, "not a portal file: expected a PRT1, PRT2 or PRT1-AM header, found " + quoted(magic));
    }

    // PRT2: line c lists the leaves of cluster c, ending with -1. Every leaf exactly once.
    void read_cluster_lines(PrtFile& prt)
    {
        constexpr uint32_t kNone = ~0u;
        // Each leaf is listed once, in at least two bytes ("0 "): a header declaring more leaves
        // than the rest of the text can list must not drive the allocation below.
        skip_space();
        const size_t remaining = text_.size() - pos_;
        if (prt.leaf_count > remaining / 2 + 1)
            fail(pos_, "the header declares " + std::to_string(prt.leaf_count) + " leaves, but the " +
                           std::to_string(remaining) + " bytes left cannot list them in cluster lines");
        prt.cluster_of_leaf.assign(prt.leaf_count, kNone);
        for (uint32_t cluster = 0; cluster < prt.cluster_count; ++cluster) {
            const std::string where = "cluster " + std::to_string(cluster) + " of " + std::to_string(prt.cluster_count);
            for (;;) {
                size_t at = 0;
                const int64_t leaf = read_portal_integer("leaf number or -1", where, at);
                if (leaf == -1)
                    break;
                if (leaf < 0 || leaf >= static_cast<int64_t>(prt.leaf_count))
                    fail(at, where + ": leaf number " + std::to_string(leaf) + " is out of range (the header declares " +
                                 std::to_string(prt.leaf_count) + " leaves)");
                uint32_t& slot = prt.cluster_of_leaf[static_cast<size_t>(leaf)];
                if (slot != kNone)
                    fail(at, where + ": leaf " + std::to_string(leaf) + " is already in cluster " + std::to_string(slot));
                slot = cluster;
            }
        }
        const auto unlisted = std::find(prt.cluster_of_leaf.begin(), prt.cluster_of_leaf.end(), kNone);
        if (unlisted != prt.cluster_of_leaf.end())
            fail(pos_, "leaf " + std::to_string(unlisted - prt.cluster_of_leaf.begin()) + " is in no cluster (" +
                           std::to_string(prt.cluster_count) + " cluster lines read)");
    }

    // PRT1-AM: the cluster of each leaf, leaf_count integers.
    void read_leaf_clusters(PrtFile& prt)
    {
        prt.cluster_of_leaf.reserve(std::min<size_t>(prt.leaf_count, (text_.size() - pos_) / 2 + 1));
        for (uint32_t leaf = 0; leaf < prt.leaf_count; ++leaf) {
            const std::string where = "the cluster map, leaf " + std::to_string(leaf) + " of " +
                                      std::to_string(prt.leaf_count);
            size_t at = 0;
            const int64_t cluster = read_portal_integer("cluster number", where, at);
            if (cluster < 0 || cluster >= static_cast<int64_t>(prt.cluster_count))
                fail(at, where + ": cluster number " + std::to_string(cluster) + " is out of range (the header declares " +
                             std::to_string(prt.cluster_count) + " clusters)");
            prt.cluster_of_leaf.push_back(static_cast<uint32_t>(cluster));
        }
    }

    // A header count; `at`, when given, gets the token's offset.
    int64_t read_count(const char* what, size_t* at = nullptr)
    {
        skip_space();
        const size_t start = pos_;
        if (at != nullptr)
            *at = start;
        const std::string_view token = any_token();
        if (token.empty())
            fail(start, std::string("file ends early: expected the ") + what);
        int64_t value = 0;
        const NumberStatus status = parse_integer(token, value);
        if (status == NumberStatus::Invalid)
            fail(start, std::string("expected the ") + what + " (an integer), found " + quoted(token));
        if (value < 0 || (status == NumberStatus::OutOfRange && token[0] == '-'))
            fail(start, std::string("negative ") + what + " " + quoted(token));
        if (status == NumberStatus::OutOfRange || value > kMaxCount)
            fail(start, std::string(what) + " " + quoted(token) + " is too large (at most " +
                            std::to_string(kMaxCount) + ")");
        return value;
    }

    // An integer of a portal line; `what` names it for messages. `start` gets the token's offset.
    int64_t read_portal_integer(const char* what, const std::string& where, size_t& start)
    {
        skip_space();
        start = pos_;
        const std::string_view token = any_token();
        if (token.empty() && pos_ == text_.size())
            fail(start, "file ends early in " + where + ": expected the " + what);
        int64_t value = 0;
        const NumberStatus status = parse_integer(token, value);
        if (status == NumberStatus::Invalid)
            fail(start, where + ": expected the " + what + " (an integer), found " + quoted(token));
        if (status == NumberStatus::OutOfRange)
            fail(start, where + ": " + what + " " + quoted(token) + " is out of range");
        return value;
    }

    void read_portal(PrtFile& prt, int64_t portal, int64_t portal_count)
    {
        const std::string where = "portal " + std::to_string(portal);
        skip_space();
        if (pos_ == text_.size())
            fail(pos_, "file ends early: portal " + std::to_string(portal) + " of " + std::to_string(portal_count) +
                           " is missing");
        size_t count_at = 0, leaf0_at = 0, leaf1_at = 0;
        const int64_t point_count = read_portal_integer("point count", where, count_at);
        const int64_t leaf0 = read_portal_integer("first leaf number", where, leaf0_at);
        const int64_t leaf1 = read_portal_integer("second leaf number", where, leaf1_at);

        // Look at the first '(' before judging the numbers: a Quake 3 file puts one more number
        // here, and would otherwise be reported as a bad point count or leaf number.
        skip_space();
        if (pos_ == text_.size())
            fail(pos_, "file ends early in " + where + ": expected '(' to start its first point");
        if (text_[pos_] != '(') {
            const size_t start = pos_;
            const std::string_view token = any_token();
            int64_t ignored = 0;
            std::string reason = where + ": expected '(' to start its first point, found " + quoted(token);
            if (parse_integer(token, ignored) == NumberStatus::Ok)
                reason += " (a Quake 3 portal file has a hint flag here or a face count in the header; "
                          "only Quake 1's PRT1, PRT2 and PRT1-AM are supported)";
            fail(start, reason);
        }

        if (point_count < kPrtMinPoints || point_count > kPrtMaxPoints)
            fail(count_at, where + " has " + std::to_string(point_count) + " points; a portal needs " +
                               std::to_string(kPrtMinPoints) + " to " + std::to_string(kPrtMaxPoints));
        const bool clusters = prt.has_clusters();
        const uint32_t limit = clusters ? prt.cluster_count : prt.leaf_count;
        const std::string unit = clusters ? "cluster" : "leaf";
        const std::string units = clusters ? "clusters" : "leaves";
        const auto check_leaf = [&](int64_t leaf, size_t at) {
            if (leaf < 0 || leaf >= static_cast<int64_t>(limit))
                fail(at, where + ": " + unit + " number " + std::to_string(leaf) + " is out of range (the header declares " +
                             std::to_string(limit) + " " + units +
                             (limit > 0 ? ", numbered 0.." + std::to_string(limit - 1) : "") + ")");
        };
        check_leaf(leaf0, leaf0_at);
        check_leaf(leaf1, leaf1_at);

        std::vector<glm::vec3>& points = prt.portals.points;
        if (points.size() + static_cast<size_t>(point_count) > std::numeric_limits<uint32_t>::max())
            fail(count_at, where + ": more than 2^32 points in the file");
        Portal out;
        out.regions[0] = static_cast<int32_t>(leaf0);
        out.regions[1] = static_cast<int32_t>(leaf1);
        out.first_point = static_cast<uint32_t>(points.size());
        out.point_count = static_cast<uint32_t>(point_count);
        for (int64_t p = 0; p < point_count; ++p)
            points.push_back(read_point(where + " point " + std::to_string(p + 1) + " of " + std::to_string(point_count)));
        prt.portals.portals.push_back(out);
    }

    glm::vec3 read_point(const std::string& where)
    {
        skip_space();
        if (pos_ == text_.size())
            fail(pos_, "file ends early in " + where + ": expected '('");
        if (text_[pos_] != '(') {
            const size_t start = pos_;
            fail(start, where + ": expected '(', found " + quoted(any_token()));
        }
        ++pos_;
        glm::vec3 point(0.0f);
        for (int axis = 0; axis < 3; ++axis) {
            skip_space();
            const size_t start = pos_;
            const std::string_view token = any_token();
            if (pos_ == text_.size() && token.empty())
                fail(start, "file ends early in " + where + ": expected 3 coordinates in a point");
            if (token.empty() || token == "(" || token == ")")
                fail(start, where + ": expected 3 coordinates in a point, found " + quoted(token) + " after " +
                                std::to_string(axis));
            float value = 0.0f;
            const NumberStatus status = parse_float(token, value);
            if (status == NumberStatus::Invalid)
                fail(start, where + ": expected a coordinate (a number), found " + quoted(token));
            if (status == NumberStatus::OutOfRange)
                fail(start, where + ": coordinate " + quoted(token) + " is outside the float range");
            if (!std::isfinite(value))
                fail(start, where + ": coordinate " + quoted(token) + " is not a finite number");
            point[axis] = value;
        }
        skip_space();
        if (pos_ == text_.size())
            fail(pos_, "file ends early in " + where + ": expected ')'");
        if (text_[pos_] != ')') {
            const size_t start = pos_;
            fail(start, where + ": expected ')' after 3 coordinates, found " + quoted(any_token()));
        }
        ++pos_;
        return point;
    }

    std::string_view text_;
    const std::string& file_;
    size_t pos_ = 0;
};

void append_number(std::string& out, float value)
{
    char buffer[64]; // FLT_MAX in fixed notation is 39 digits
    // Integral values in fixed notation: their exact integer digits ("880", "-0", and for the rare
    // huge float "100000002004087734272"), never a decimal point or an exponent. Others in the
    // shortest form that reads back to the same float ("0.1", "-1e-07").
    const std::to_chars_result result = value == std::trunc(value)
                                            ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed)
                                            : std::to_chars(buffer, buffer + sizeof buffer, value);
    assert(result.ec == std::errc());
    out.append(buffer, result.ptr);
}

// PRT2's cluster lines: each cluster's leaves in increasing order, then -1 (validated map).
void append_cluster_lines(std::string& out, const PrtFile& prt)
{
    std::vector<std::vector<uint32_t>> leaves(prt.cluster_count);
    for (uint32_t leaf = 0; leaf < prt.leaf_count; ++leaf)
        leaves[prt.cluster_of_leaf[leaf]].push_back(leaf);
    for (const std::vector<uint32_t>& cluster : leaves) {
        for (const uint32_t leaf : cluster) {
            out += std::to_string(leaf);
            out += ' ';
        }
        out += "-1\n";
    }
}

void validate_for_writing(const PrtFile& prt)
{
    const auto bad = [](const std::string& reason) { throw std::invalid_argument("format_prt: " + reason); };
    if (prt.leaf_count > static_cast<uint64_t>(kMaxCount))
        bad("leaf count " + std::to_string(prt.leaf_count) + " is too large");
    if (prt.portals.portals.size() > static_cast<uint64_t>(kMaxCount))
        bad("too many portals");
    if (prt.has_clusters()) {
        if (prt.cluster_count > static_cast<uint64_t>(kMaxCount))
            bad("cluster count " + std::to_string(prt.cluster_count) + " is too large");
        if (prt.cluster_of_leaf.size() != prt.leaf_count)
            bad("the cluster map has " + std::to_string(prt.cluster_of_leaf.size()) + " entries for " +
                std::to_string(prt.leaf_count) + " leaves");
        for (size_t leaf = 0; leaf < prt.cluster_of_leaf.size(); ++leaf)
            if (prt.cluster_of_leaf[leaf] >= prt.cluster_count)
                bad("leaf " + std::to_string(leaf) + " has cluster " + std::to_string(prt.cluster_of_leaf[leaf]) +
                    ", out of range for " + std::to_string(prt.cluster_count) + " clusters");
    }
    const std::vector<glm::vec3>& points = prt.portals.points;
    for (size_t i = 0; i < prt.portals.portals.size(); ++i) {
        const Portal& portal = prt.portals.portals[i];
        const std::string where = "portal " + std::to_string(i);
        if (portal.point_count < kPrtMinPoints || portal.point_count > kPrtMaxPoints)
            bad(where + " has " + std::to_string(portal.point_count) + " points; a PRT1 portal needs 3 to 64");
        if (static_cast<uint64_t>(portal.first_point) + portal.point_count > points.size())
            bad(where + ": points " + std::to_string(portal.first_point) + "+" + std::to_string(portal.point_count) +
                " run past the " + std::to_string(points.size()) + " points of the set");
        const uint32_t limit = prt.has_clusters() ? prt.cluster_count : prt.leaf_count;
        for (const int32_t region : portal.regions)
            if (region < 0 || static_cast<uint32_t>(region) >= limit)
                bad(where + ": " + (prt.has_clusters() ? "cluster " : "leaf ") + std::to_string(region) +
                    " is out of range for " + std::to_string(limit) + (prt.has_clusters() ? " clusters" : " leaves"));
        for (uint32_t p = 0; p < portal.point_count; ++p)
            for (int axis = 0; axis < 3; ++axis)
                if (!std::isfinite(points[portal.first_point + p][axis]))
                    bad(where + ": a coordinate is not finite");
    }
}

} // namespace

PrtFile parse_prt(std::string_view text, const std::string& file_name_for_errors)
{
    return PrtParser(text, file_name_for_errors).parse();
}

PrtFile load_prt(const std::string& path)
{
    const std::vector<uint8_t> bytes = read_whole_file(path);
    return parse_prt(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path);
}

std::string format_prt(const PrtFile& prt)
{
    validate_for_writing(prt);
    std::string out = prt.has_clusters() ? "PRT2\n" + std::to_string(prt.leaf_count) + "\n" +
                                               std::to_string(prt.cluster_count) + "\n"
                                         : "PRT1\n" + std::to_string(prt.leaf_count) + "\n";
    out += std::to_string(prt.portals.portals.size()) + "\n";
    out.reserve(out.size() + prt.portals.portals.size() * 16 + prt.portals.points.size() * 24);
    for (const Portal& portal : prt.portals.portals) {
        out += std::to_string(portal.point_count);
        out += ' ';
        out += std::to_string(portal.regions[0]);
        out += ' ';
        out += std::to_string(portal.regions[1]);
        out += ' ';
        for (uint32_t p = 0; p < portal.point_count; ++p) {
            const glm::vec3& point = prt.portals.points[portal.first_point + p];
            out += '(';
            for (int axis = 0; axis < 3; ++axis) {
                append_number(out, point[axis]);
                out += ' ';
            }
            out += ") ";
        }
        out += '\n';
    }
    if (prt.has_clusters())
        append_cluster_lines(out, prt);
    return out;
}

void save_prt(const std::string& path, const PrtFile& prt)
{
    const std::string text = format_prt(prt);
    write_whole_file(path, std::vector<uint8_t>(text.begin(), text.end()));
}

Plane portal_plane(const PortalSet& set, const Portal& portal)
{
    assert(portal.point_count >= 3 && static_cast<uint64_t>(portal.first_point) + portal.point_count <= set.points.size());
    const glm::dvec3 p0(set.points[portal.first_point]);
    const glm::dvec3 p1(set.points[portal.first_point + 1]);
    const glm::dvec3 p2(set.points[portal.first_point + 2]);
    const glm::dvec3 cross = glm::cross(p0 - p1, p2 - p1);
    const double length = glm::length(cross);
    if (!(length > 0.0) || !std::isfinite(length))
        return Plane{glm::vec3(0.0f), 0.0f};
    const glm::dvec3 normal = cross / length;
    return Plane{glm::vec3(normal), static_cast<float>(glm::dot(normal, p0))};
}

} // namespace pvs::quake
