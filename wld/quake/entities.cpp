#include "wld/quake/entities.h"

#include "visibility/file_error.h"

namespace pvs::quake {

std::optional<std::string_view> Entity::get(std::string_view key) const
{
    for (const auto& [k, v] : pairs)
        if (k == key)
            return v;
    return std::nullopt;
}

namespace {

class EntityLexer {
public:
    EntityLexer(std::span<const uint8_t> text, const std::string& file, uint64_t base)
        : text_(text), file_(file), base_(base)
    {
    }

    // Skips whitespace; true when only whitespace or NULs remain.
    bool at_end()
    {
        while (pos_ < text_.size() && (text_[pos_] <= ' '))
            ++pos_;
        return pos_ >= text_.size();
    }
    char peek() const { return static_cast<char>(text_[pos_]); }
    size_t pos() const { return pos_; }
    void advance() { ++pos_; }

    std::string quoted()
    {
        if (at_end() || peek() != '"')
            fail("expected a quoted string");
        const size_t start = ++pos_;
        while (pos_ < text_.size() && text_[pos_] != '"' && text_[pos_] != 0)
            ++pos_;
        if (pos_ >= text_.size() || text_[pos_] != '"')
            fail_at(start - 1, "unterminated string");
        std::string s(reinterpret_cast<const char*>(text_.data()) + start, pos_ - start);
        ++pos_;
        return s;
    }

    [[noreturn]] void fail(const std::string& reason) const { fail_at(pos_, reason); }
    [[noreturn]] void fail_at(size_t at, const std::string& reason) const
    {
        throw FileError(file_, base_ + at, "entities: " + reason);
    }

private:
    std::span<const uint8_t> text_;
    const std::string& file_;
    uint64_t base_;
    size_t pos_ = 0;
};

} // namespace

std::vector<Entity> parse_entities(std::span<const uint8_t> text, const std::string& file, uint64_t lump_offset)
{
    std::vector<Entity> entities;
    EntityLexer lex(text, file, lump_offset);
    while (!lex.at_end()) {
        if (lex.peek() != '{')
            lex.fail("expected '{' to open an entity");
        Entity entity;
        entity.offset = lump_offset + lex.pos();
        const size_t open = lex.pos();
        lex.advance();
        for (;;) {
            if (lex.at_end())
                lex.fail_at(open, "entity is not closed by '}'");
            if (lex.peek() == '}') {
                lex.advance();
                break;
            }
            std::string key = lex.quoted();
            std::string value = lex.quoted();
            entity.pairs.emplace_back(std::move(key), std::move(value));
        }
        entities.push_back(std::move(entity));
    }
    return entities;
}

} // namespace pvs::quake
