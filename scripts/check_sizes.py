#!/usr/bin/env python3
"""Checks the source tree's size rules: no .cxx in the library modules over MAX_FILE lines and
no function there or in the program over MAX_FUNCTION lines (declarative option tables, marked
by a '// size: table' comment on the line before, aside).

Usage: check_sizes.py [--report] [ROOT]. Exits 1 and names each breach; --report prints every
file's and every long function's line count as well."""
import pathlib
import re
import sys

MAX_FILE = 900
MAX_FUNCTION = 150
FILE_DIRS = ("Passes", "IO", "Filters", "Figures")
FUNCTION_DIRS = FILE_DIRS + ("Applications",)


def strip_code(text):
    """The text with comments, strings and character literals blanked (newlines kept)."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            if not m:
                out.append(c)
                i += 1
                continue
            end = ")" + m.group(1) + '"'
            j = text.find(end, i + m.end())
            j = n if j < 0 else j + len(end)
            out.append('""' + "\n" * text.count("\n", i, j))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(path):
    """(name, first line, line count) of each function body in a C++ file: a brace whose
    opening follows ')' (after qualifiers) at namespace or class level."""
    raw = path.read_text(errors="replace")
    raw_lines = raw.splitlines()
    code = strip_code(raw)
    result = []
    stack = []  # per open brace: (kind, start offset, start line)
    line = 1
    last_stmt = 0
    for i, c in enumerate(code):
        if c == "\n":
            line += 1
        elif c == "{":
            head = code[last_stmt:i]
            inside_function = any(entry[0] == "function" for entry in stack)
            kind = "block"
            if not inside_function:
                tail = re.sub(r"\b(const|override|final|noexcept|volatile|mutable)\b", "", head)
                tail = re.sub(r"->\s*[\w:<>,\s*&]+$", "", tail.rstrip())
                tail = re.sub(r"(?<!:):(?!:)\s*[\w:]+\s*\([^{}]*\)\s*(,\s*[\w:]+\s*[({][^{}]*[)}]\s*)*$", "", tail.rstrip())
                if tail.rstrip().endswith(")") and not re.search(r"\b(if|for|while|switch|catch)\s*\(", tail):
                    kind = "function"
            stack.append((kind, i, line, head))
            last_stmt = i + 1
        elif c == "}":
            if stack:
                kind, start, start_line, head = stack.pop()
                if kind == "function":
                    m = re.findall(r"([~\w:]+)\s*\(", head)
                    name = m[0] if m else "?"
                    previous = raw_lines[start_line - 2] if start_line >= 2 else ""
                    sig_line = start_line - head.lstrip().count("\n")
                    before = raw_lines[sig_line - 2] if sig_line >= 2 else ""
                    if "size: table" in before or "size: table" in previous:
                        pass
                    else:
                        result.append((name, sig_line, line - sig_line + 1))
            last_stmt = i + 1
        elif c == ";":
            last_stmt = i + 1
    return result


def main(argv):
    report = "--report" in argv
    args = [a for a in argv if not a.startswith("--")]
    root = pathlib.Path(args[0] if args else pathlib.Path(__file__).resolve().parents[1])
    breaches = []
    for d in FUNCTION_DIRS:
        for path in sorted((root / d).rglob("*.cxx")) if (root / d).exists() else []:
            rel = path.relative_to(root)
            count = len(path.read_text(errors="replace").splitlines())
            if d in FILE_DIRS:
                if report:
                    print(f"{count:6d}  {rel}")
                if count > MAX_FILE:
                    breaches.append(f"{rel}: {count} lines (at most {MAX_FILE})")
            for name, first, length in functions(path):
                if report and length > 100:
                    print(f"{length:6d}  {rel}:{first} {name}()")
                if length > MAX_FUNCTION:
                    breaches.append(f"{rel}:{first}: {name}() is {length} lines (at most {MAX_FUNCTION})")
    for b in breaches:
        print(b)
    print(f"{len(breaches)} size breaches")
    return 1 if breaches else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
