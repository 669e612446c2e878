#include "xlsx_writer.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

#include "zip_writer.hpp"

namespace dragon::xlsx {

namespace {

constexpr std::string_view kXmlDecl = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n";
constexpr std::string_view kMainNs = "http://schemas.openxmlformats.org/spreadsheetml/2006/main";
constexpr std::string_view kRelNs = "http://schemas.openxmlformats.org/officeDocument/2006/relationships";

// Appends a column's letters (0 -> A, 25 -> Z, 26 -> AA, 16383 -> XFD).
void append_column(std::string& out, std::uint32_t col) {
    char letters[4];
    int n = 0;
    for (std::uint32_t c = col + 1; c > 0; c = (c - 1) / 26) letters[n++] = static_cast<char>('A' + (c - 1) % 26);
    while (n > 0) out.push_back(letters[--n]);
}

void append_cell_name(std::string& out, std::uint32_t row, std::uint32_t col) {
    append_column(out, col);
    fmt::format_to(std::back_inserter(out), "{}", row + 1);
}

// The code points of valid UTF-8 text, one at a time; std::invalid_argument for anything else
// (overlong forms, surrogates, past U+10FFFF, cut short).
template <class Each>
void each_code_point(std::string_view s, Each&& each) {
    std::size_t i = 0;
    const auto bad = [&] {
        throw std::invalid_argument(fmt::format("a string that is not valid UTF-8 (byte {} of {})", i + 1, s.size()));
    };
    while (i < s.size()) {
        const auto b = static_cast<unsigned char>(s[i]);
        std::size_t len;
        char32_t cp;
        if (b < 0x80) {
            len = 1, cp = b;
        } else if (b >= 0xC2 && b <= 0xDF) {
            len = 2, cp = b & 0x1F;
        } else if (b >= 0xE0 && b <= 0xEF) {
            len = 3, cp = b & 0x0F;
        } else if (b >= 0xF0 && b <= 0xF4) {
            len = 4, cp = b & 0x07;
        } else {
            bad();
            return;
        }
        if (i + len > s.size()) bad();
        for (std::size_t k = 1; k < len; ++k) {
            const auto c = static_cast<unsigned char>(s[i + k]);
            if ((c & 0xC0) != 0x80) bad();
            cp = (cp << 6) | (c & 0x3F);
        }
        if ((len == 3 && (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF))) || (len == 4 && (cp < 0x10000 || cp > 0x10FFFF)))
            bad();
        each(i, len, cp);
        i += len;
    }
}

bool is_hex(char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }

// Text as XML character data in an OOXML string (ST_Xstring): &, <, > escaped; a carriage
// return as a reference (a parser would turn a literal one into a line feed); characters XML
// cannot hold (controls, U+FFFE, U+FFFF) as Excel writes them, _xHHHH_, and a literal "_xHHHH_"
// with its underscore escaped (_x005F_) so that it reads back as written.
void append_text(std::string& out, std::string_view s) {
    each_code_point(s, [&](std::size_t at, std::size_t len, char32_t cp) {
        if (cp == '&') {
            out += "&amp;";
        } else if (cp == '<') {
            out += "&lt;";
        } else if (cp == '>') {
            out += "&gt;";
        } else if (cp == '\r') {
            out += "&#13;";
        } else if ((cp < 0x20 && cp != '\t' && cp != '\n') || cp == 0xFFFE || cp == 0xFFFF) {
            fmt::format_to(std::back_inserter(out), "_x{:04X}_", static_cast<std::uint32_t>(cp));
        } else if (cp == '_' && at + 7 <= s.size() && s[at + 1] == 'x' && is_hex(s[at + 2]) && is_hex(s[at + 3]) &&
                   is_hex(s[at + 4]) && is_hex(s[at + 5]) && s[at + 6] == '_') {
            out += "_x005F_";
        } else {
            out.append(s.substr(at, len));
        }
    });
}

// An attribute value between double quotes.
void append_attribute(std::string& out, std::string_view s) {
    for (const char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out.push_back(c);
        }
    }
}

// Whitespace an XML reader may drop unless told to keep it: at either end, a tab or a line break.
bool needs_preserve(std::string_view s) {
    if (s.empty()) return false;
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    return space(s.front()) || space(s.back()) || s.find_first_of("\t\n\r") != std::string_view::npos;
}

std::size_t utf16_length(std::string_view s) {
    std::size_t n = 0;
    each_code_point(s, [&](std::size_t, std::size_t, char32_t cp) { n += cp > 0xFFFF ? 2 : 1; });
    return n;
}

std::string ascii_lower(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return out;
}

}  // namespace

std::string cell_name(std::uint32_t row, std::uint32_t col) {
    std::string out;
    append_cell_name(out, row, col);
    return out;
}

// ---- Sheet --------------------------------------------------------------------------------

void Sheet::check_cell(std::uint32_t row, std::uint32_t col) const {
    if (row >= kMaxRows || col >= kMaxColumns)
        throw std::out_of_range(fmt::format("the cell at row {}, column {} is past a sheet's {} rows and {} columns",
                                            row + 1, col + 1, kMaxRows, kMaxColumns));
    if (any_ && (row < row_ || (row == row_ && col <= col_)))
        throw std::invalid_argument(fmt::format("sheet '{}': the cell {} comes after {}: cells are written row by row, "
                                                "left to right",
                                                name_, cell_name(row, col), cell_name(row_, col_)));
}

void Sheet::open_cell(std::uint32_t row, std::uint32_t col) {
    check_cell(row, col);
    if (!any_ || row != row_) {
        if (row_open_) rows_ += "</row>";
        fmt::format_to(std::back_inserter(rows_), "<row r=\"{}\">", row + 1);
        row_open_ = true;
    }
    if (!any_) min_row_ = row, min_col_ = col;
    min_col_ = std::min(min_col_, col);
    max_row_ = row;
    max_col_ = std::max(max_col_, col);
    any_ = true;
    row_ = row, col_ = col;
    rows_ += "<c r=\"";
    append_cell_name(rows_, row, col);
    rows_ += '"';
}

void Sheet::write_string(std::uint32_t row, std::uint32_t col, std::string_view text) {
    check_cell(row, col);  // a refused cell or text leaves the sheet and the strings as they were
    const std::uint32_t id = book_->string_index(text);
    open_cell(row, col);
    fmt::format_to(std::back_inserter(rows_), " t=\"s\"><v>{}</v></c>", id);
}

void Sheet::write_number(std::uint32_t row, std::uint32_t col, double value) {
    open_cell(row, col);
    if (!std::isfinite(value)) {
        rows_ += " t=\"e\"><v>#NUM!</v></c>";
        return;
    }
    rows_ += "><v>";
    fmt::format_to(std::back_inserter(rows_), "{}", value);  // shortest round trip
    rows_ += "</v></c>";
}

std::string Sheet::head() const {
    std::string h(kXmlDecl);
    h += fmt::format("<worksheet xmlns=\"{}\" xmlns:r=\"{}\"><dimension ref=\"", kMainNs, kRelNs);
    if (!any_) {
        h += "A1";
    } else {
        append_cell_name(h, min_row_, min_col_);
        if (max_row_ != min_row_ || max_col_ != min_col_) {
            h += ':';
            append_cell_name(h, max_row_, max_col_);
        }
    }
    h += "\"/><sheetViews><sheetView workbookViewId=\"0\"/></sheetViews><sheetFormatPr defaultRowHeight=\"15\"/>";
    h += any_ ? "<sheetData>" : "<sheetData/>";
    return h;
}

std::string_view Sheet::tail() const {
    constexpr std::string_view rows_end = "</row></sheetData>";
    constexpr std::string_view closing =
        "</row></sheetData><pageMargins left=\"0.7\" right=\"0.7\" top=\"0.75\" bottom=\"0.75\" header=\"0.3\" "
        "footer=\"0.3\"/></worksheet>";
    return any_ ? closing : closing.substr(rows_end.size());
}

// ---- Workbook -----------------------------------------------------------------------------

Sheet& Workbook::add_sheet(std::string_view name) {
    const std::size_t length = utf16_length(name);  // also checks the UTF-8
    if (length == 0 || length > 31)
        throw std::invalid_argument(fmt::format("a sheet name of {} characters ('{}'): 1 to 31", length, name));
    if (name.find_first_of("[]:*?/\\") != std::string_view::npos || name.front() == '\'' || name.back() == '\'')
        throw std::invalid_argument(fmt::format("the sheet name '{}' holds one of []:*?/\\ or starts or ends with '", name));
    for (const auto& s : sheets_)
        if (ascii_lower(s->name()) == ascii_lower(name))
            throw std::invalid_argument(fmt::format("two sheets named '{}'", name));
    sheets_.push_back(std::unique_ptr<Sheet>(new Sheet(std::string(name), *this)));
    return *sheets_.back();
}

std::uint32_t Workbook::string_index(std::string_view text) {
    std::string key(text);
    const auto found = string_ids_.find(key);
    if (found != string_ids_.end()) {
        ++string_uses_;
        return found->second;
    }
    std::string si = "<si><t";
    if (needs_preserve(text)) si += " xml:space=\"preserve\"";
    si += '>';
    append_text(si, text);  // throws for text that is not UTF-8, before anything is kept
    si += "</t></si>";
    strings_ += si;
    const auto id = static_cast<std::uint32_t>(string_ids_.size());
    string_ids_.emplace(std::move(key), id);
    ++string_uses_;
    return id;
}

template <class Zip>
void Workbook::pack(Zip& zip, int level) const {
    const std::size_t n = sheets_.size();
    std::string types(kXmlDecl);
    types +=
        "<Types xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\">"
        "<Default Extension=\"rels\" ContentType=\"application/vnd.openxmlformats-package.relationships+xml\"/>"
        "<Default Extension=\"xml\" ContentType=\"application/xml\"/>"
        "<Override PartName=\"/docProps/app.xml\" "
        "ContentType=\"application/vnd.openxmlformats-officedocument.extended-properties+xml\"/>"
        "<Override PartName=\"/docProps/core.xml\" "
        "ContentType=\"application/vnd.openxmlformats-package.core-properties+xml\"/>"
        "<Override PartName=\"/xl/styles.xml\" "
        "ContentType=\"application/vnd.openxmlformats-officedocument.spreadsheetml.styles+xml\"/>"
        "<Override PartName=\"/xl/workbook.xml\" "
        "ContentType=\"application/vnd.openxmlformats-officedocument.spreadsheetml.sheet.main+xml\"/>"
        "<Override PartName=\"/xl/sharedStrings.xml\" "
        "ContentType=\"application/vnd.openxmlformats-officedocument.spreadsheetml.sharedStrings+xml\"/>";
    for (std::size_t k = 1; k <= n; ++k)
        types += fmt::format("<Override PartName=\"/xl/worksheets/sheet{}.xml\" "
                             "ContentType=\"application/vnd.openxmlformats-officedocument.spreadsheetml.worksheet+xml\"/>",
                             k);
    types += "</Types>";
    zip.add("[Content_Types].xml", types, level);

    std::string rels(kXmlDecl);
    rels +=
        "<Relationships xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\">"
        "<Relationship Id=\"rId1\" Type=\"http://schemas.openxmlformats.org/officeDocument/2006/relationships/"
        "officeDocument\" Target=\"xl/workbook.xml\"/>"
        "<Relationship Id=\"rId2\" Type=\"http://schemas.openxmlformats.org/package/2006/relationships/metadata/"
        "core-properties\" Target=\"docProps/core.xml\"/>"
        "<Relationship Id=\"rId3\" Type=\"http://schemas.openxmlformats.org/officeDocument/2006/relationships/"
        "extended-properties\" Target=\"docProps/app.xml\"/></Relationships>";
    zip.add("_rels/.rels", rels, level);

    std::string app(kXmlDecl);
    app +=
        "<Properties xmlns=\"http://schemas.openxmlformats.org/officeDocument/2006/extended-properties\" "
        "xmlns:vt=\"http://schemas.openxmlformats.org/officeDocument/2006/docPropsVTypes\">"
        "<Application>benchdragon</Application></Properties>";
    zip.add("docProps/app.xml", app, level);

    std::string core(kXmlDecl);
    core += fmt::format(
        "<cp:coreProperties xmlns:cp=\"http://schemas.openxmlformats.org/package/2006/metadata/core-properties\" "
        "xmlns:dc=\"http://purl.org/dc/elements/1.1/\" xmlns:dcterms=\"http://purl.org/dc/terms/\" "
        "xmlns:dcmitype=\"http://purl.org/dc/dcmitype/\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\">"
        "<dcterms:created xsi:type=\"dcterms:W3CDTF\">{0}</dcterms:created>"
        "<dcterms:modified xsi:type=\"dcterms:W3CDTF\">{0}</dcterms:modified></cp:coreProperties>",
        kCreated);
    zip.add("docProps/core.xml", core, level);

    std::string workbook(kXmlDecl);
    workbook += fmt::format("<workbook xmlns=\"{}\" xmlns:r=\"{}\"><bookViews><workbookView/></bookViews><sheets>",
                            kMainNs, kRelNs);
    for (std::size_t k = 0; k < n; ++k) {
        workbook += "<sheet name=\"";
        append_attribute(workbook, sheets_[k]->name());
        workbook += fmt::format("\" sheetId=\"{0}\" r:id=\"rId{0}\"/>", k + 1);
    }
    workbook += "</sheets></workbook>";
    zip.add("xl/workbook.xml", workbook, level);

    std::string book_rels(kXmlDecl);
    book_rels += "<Relationships xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\">";
    for (std::size_t k = 1; k <= n; ++k)
        book_rels += fmt::format("<Relationship Id=\"rId{0}\" Type=\"{1}/worksheet\" Target=\"worksheets/sheet{0}.xml\"/>",
                                 k, kRelNs);
    book_rels += fmt::format("<Relationship Id=\"rId{}\" Type=\"{}/styles\" Target=\"styles.xml\"/>", n + 1, kRelNs);
    book_rels +=
        fmt::format("<Relationship Id=\"rId{}\" Type=\"{}/sharedStrings\" Target=\"sharedStrings.xml\"/>", n + 2, kRelNs);
    book_rels += "</Relationships>";
    zip.add("xl/_rels/workbook.xml.rels", book_rels, level);

    std::string styles(kXmlDecl);
    styles += fmt::format(
        "<styleSheet xmlns=\"{}\">"
        "<fonts count=\"1\"><font><sz val=\"11\"/><name val=\"Calibri\"/><family val=\"2\"/>"
        "<scheme val=\"minor\"/></font></fonts>"
        "<fills count=\"2\"><fill><patternFill patternType=\"none\"/></fill>"
        "<fill><patternFill patternType=\"gray125\"/></fill></fills>"
        "<borders count=\"1\"><border><left/><right/><top/><bottom/><diagonal/></border></borders>"
        "<cellStyleXfs count=\"1\"><xf numFmtId=\"0\" fontId=\"0\" fillId=\"0\" borderId=\"0\"/></cellStyleXfs>"
        "<cellXfs count=\"1\"><xf numFmtId=\"0\" fontId=\"0\" fillId=\"0\" borderId=\"0\" xfId=\"0\"/></cellXfs>"
        "<cellStyles count=\"1\"><cellStyle name=\"Normal\" xfId=\"0\" builtinId=\"0\"/></cellStyles>"
        "<dxfs count=\"0\"/><tableStyles count=\"0\"/></styleSheet>",
        kMainNs);
    zip.add("xl/styles.xml", styles, level);

    const std::string strings_head =
        fmt::format("{}<sst xmlns=\"{}\" count=\"{}\" uniqueCount=\"{}\">", kXmlDecl, kMainNs, string_uses_,
                    string_ids_.size());
    zip.add("xl/sharedStrings.xml", {strings_head, strings_, "</sst>"}, level);

    for (std::size_t k = 0; k < n; ++k) {
        const Sheet& s = *sheets_[k];
        const std::string head = s.head();
        zip.add(fmt::format("xl/worksheets/sheet{}.xml", k + 1), {head, s.rows_, s.tail()}, level);
    }
}

void Workbook::save(const std::string& path, int level) const {
    zip::ZipWriter zip(path);
    pack(zip, level);
    zip.finish();
}

std::string Workbook::bytes(int level) const {
    zip::ZipWriter zip;
    pack(zip, level);
    return zip.finish();
}

}  // namespace dragon::xlsx
