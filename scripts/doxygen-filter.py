#!/usr/bin/env python3
"""Reads a header of include/dragon/ and prints it as Doxygen reads it.

The headers are commented in the house style, with plain // comments: a block above a
declaration says what it is, a comment after a member says what it holds. Doxygen documents
only its own comment markers, so this filter (Doxyfile's INPUT_FILTER) rewrites the markers on
the way in, and the headers stay as they are:
  - the block at the top of a file, before any code, documents the file (it moves to a \\file
    block at the end, its lines left blank);
  - a comment line of its own becomes ///, documenting what follows it;
  - a comment after code on the same line becomes ///<, documenting that line's member, and so
    do comment lines beneath it that start in its column (its continuation);
  - a comment above several declarations with no blank line between them documents them all
    (a Doxygen member group, DISTRIBUTE_GROUP_DOC: "// As head travel and as time" above
    travel() and time()), as a reader takes it.
Line numbers are kept, so Doxygen's warnings point at the header's own lines.
"""
import re
import sys

COMMENT_LINE = re.compile(r"^(\s*)//(?!/)(.*)$")
TAG_LIKE = re.compile(r"<(?=[A-Za-z/!?])")
LINE_END_DOTS = re.compile(r"(?<=\s)(\.+)\s*$")


def plain(text):
    """Comment text as Doxygen shows it as written: its command characters escaped (a backslash,
    an at sign), a <word> kept as text rather than taken for an HTML tag, and dots ending a line
    after a space (a range's 'a ..' going on below) kept as text rather than taken for the end
    of a list (an empty HTML comment after them, which shows as nothing)."""
    text = text.replace("\\", "\\\\").replace("@", "\\@")
    text = TAG_LIKE.sub(r"\\<", text)
    return LINE_END_DOTS.sub(r"\1<!-- -->", text)


def trailing_comment(line):
    """The column of a // comment after code on this line (not inside a string), or -1."""
    in_string = False
    i = 0
    while i < len(line) - 1:
        ch = line[i]
        if ch == '"' and (i == 0 or line[i - 1] != "\\"):
            in_string = not in_string
        elif not in_string and line.startswith("//", i):
            return i if line[:i].strip() else -1
        i += 1
    return -1


DECLARATION = re.compile(r"^\s*(?!//|/\*|\*|#|\}|public:|private:|protected:)\S.*[;}]\s*(///<.*)?$")
# Destructors and deleted copies say what they are by their form: a group stops before them.
BY_FORM = re.compile(r"^\s*(~\w+\(\)|.*=\s*delete\s*;)")
DEFAULTED_EQUALITY = re.compile(r"^(\s*)(bool operator==\(.*\) const = default;)\s*$")


def group_declarations(out):
    """Wraps each run of two or more one-line declarations that follows a /// block (no blank
    line, no comment between) in a member group."""
    i = 0
    while i < len(out):
        if out[i].lstrip().startswith("///") and not out[i].lstrip().startswith("///<"):
            j = i
            while j + 1 < len(out) and out[j + 1].lstrip().startswith("///") and not out[j + 1].lstrip().startswith("///<"):
                j += 1
            k = j + 1
            while k < len(out) and DECLARATION.match(out[k]) and "///<" not in out[k] and not BY_FORM.match(out[k]):
                k += 1
            if k - (j + 1) >= 2:
                # The group opens on a line of its own before the comment (a blank line there
                # takes it, so no line moves), so the comment documents its first member and
                # DISTRIBUTE_GROUP_DOC hands that to the rest.
                indent = out[i][: len(out[i]) - len(out[i].lstrip())]
                out[k - 1] = out[k - 1] + " ///@}"
                if i > 0 and not out[i - 1].strip():
                    out[i - 1] = indent + "///@{"
                else:
                    out.insert(i, indent + "///@{")
                    k += 1
            i = k
        else:
            i += 1


def main(path):
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    out = []
    at_top = True          # still in the file's first comment block
    file_doc = []          # that block's lines
    continuation = -1      # the column of the trailing comment above, while its lines go on
    for line in lines:
        m = COMMENT_LINE.match(line)
        if at_top:
            if m:
                file_doc.append(plain(m.group(2)))
                out.append("")
                continue
            at_top = False
        if m:
            if continuation >= 0 and len(m.group(1)) == continuation:
                out.append(m.group(1) + "///<" + plain(m.group(2)))
                continue
            continuation = -1
            out.append(m.group(1) + "///" + plain(m.group(2)))
            continue
        eq = DEFAULTED_EQUALITY.match(line)
        if eq:  # says what it is by its form: member-wise equality
            out.append(line + "  ///< Equal when every member is.")
            continuation = -1
            continue
        col = trailing_comment(line)
        code = line[:col].rstrip() if col >= 0 else line
        member = code.strip() and not code.endswith("{") and not code.lstrip().startswith(("}", "#"))
        if col >= 0 and member and not line.startswith("///", col):
            out.append(line[:col] + "///<" + plain(line[col + 2:]))
            continuation = col
        else:
            out.append(line)
            continuation = -1
    group_declarations(out)
    if file_doc:
        out.append("/** \\file")
        out.extend(" *" + text for text in file_doc)
        out.append(" */")
    sys.stdout.write("\n".join(out))


if __name__ == "__main__":
    main(sys.argv[1])
