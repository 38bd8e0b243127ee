#!/usr/bin/python3
"""Parameter reference of the VTK Stylize passes, generated from the headers and the code.

    /usr/bin/python3 scripts/parameters.py           # writes docs/PARAMETERS.md, README tables
                                                     # and the ParaView XML in Plugin/View/
    /usr/bin/python3 scripts/parameters.py --check   # verifies them, prints a diff, exit 1 on drift

Sources, so that nothing can drift:

- the parameters and their meaning: the public section of each header in Passes/ (every
  Set<Name> setter: vtkSet*Macro, or a method with a matching Get<Name>), the meaning being the
  doxygen comment above the setter (or above its ///@{ group);
- defaults: Get<Name>() of a new instance, through the Python wrapping (vtkstylize); setters
  without a getter: the member's initializer in the header;
- ranges: Get<Name>MinValue()/Get<Name>MaxValue() (vtkSetClampMacro); otherwise the range the
  comment states, confirmed by setting out-of-range values and reading them back; enum values
  from the header's enums.

The comments' own statements of ranges and defaults are compared with the code: a contradiction is
an error, like a parameter without a comment. A missing unit, range or default in a comment is a
warning. The README's parameter tables are generated copies between marker comments
(<!-- parameters:CLASS begin --> ... <!-- parameters:CLASS end -->); --check also fails on a
hand-written parameter table outside them.

The ParaView plugin's server-manager XML is generated from the same description:
Plugin/View/StylizePasses.xml (a proxy per pass, a property per parameter: kind, default, range
domain, documentation) and the blocks of Plugin/View/StylizeView.xml between its
<!-- generated:exposed:PROXY begin/end --> markers (the view's <ExposedProperties>
groups of those subproxies). Object-valued and list-valued parameters are not exposed, nor those
in XML_SKIP (set by the view).

Needs the build's python folder on PYTHONPATH (build/python and build/lib are tried when the
import fails). Only instantiates the classes: no display, no OpenGL context.
"""
import argparse
import difflib
import glob
import math
import os
import re
import sys
import textwrap
from xml.sax.saxutils import escape

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUTPUT = os.path.join("docs", "PARAMETERS.md")
README = "README.md"
DIFF_LINES = 200  # --check shows at most this many lines of each stale file's diff

# The classes documented, in order: (class, header relative to the repository root).
CLASSES = [
    ("vtkStylizeLightingPass", "Passes/vtkStylizeLightingPass.h"),
    ("vtkStylizeGBufferPass", "Passes/vtkStylizeGBufferPass.h"),
    ("vtkComicPass", "Passes/vtkComicPass.h"),
    ("vtkPixelArtPass", "Passes/vtkPixelArtPass.h"),
    ("vtkSketchPass", "Passes/vtkSketchPass.h"),
]

# Where the headers of the classes' base classes are looked for: the project, then VTK.
PROJECT_HEADER_DIRS = ["Passes", "Filters"]
VTK_HEADER_GLOB = "/usr/include/vtk-9*"
# Base classes whose public state is VTK's render-loop plumbing (e.g. vtkOpenGLRenderPass's
# ActiveDrawBuffers), not a user setting: inherited parameters are collected below them only.
FRAMEWORK_BASES = {"vtkOpenGLRenderPass", "vtkRenderPass", "vtkObject", "vtkObjectBase", "object"}

# Units recognized in a comment, first match wins (the phrase must say it is the unit).
UNIT_PATTERNS = [
    (r"\bdimensionless\b", "dimensionless"),
    (r"\bin screen pixels\b", "screen pixels"),
    (r"(?:\bin |, |\()points\b|\bpoints at the focal distance\b", "points"),
    (r"(?:\bin |, |\()pixels\b", "pixels"),
    (r"\bart pixels per\b", "art pixels"),
    (r"(?:\bin |, |\()degrees\b", "degrees"),
    (r"(?:\bin |, |\()radians\b", "radians"),
    (r"(?:\bin |, |\()world units\b", "world units"),
    (r"\b[Tt]ones? (?:above|below)\b", "tone (lit luminance)"),
    (r"\b[Nn]umber of\b|\blevels per\b|\b(?:[Hh]ysteresis|LIC) steps\b|\biterations\b|"
     r"\bmany steps\b", "count"),
]
VECTOR_UNIT_PATTERNS = [(r"\bRGB\b", "RGB")] + UNIT_PATTERNS

NUM = r"-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
NAMED_VALUES = {"on": True, "off": False, "nullptr": None, "NULL": None, "white": (1.0, 1.0, 1.0),
                "black": (0.0, 0.0, 0.0)}
SCALAR_TYPES = {"int", "double", "float", "bool", "unsigned int", "long", "vtkIdType",
                "unsigned char", "char"}
PROBE = 1.0e300
INT_PROBE = 2 ** 31 - 1


# ------------------------------------------------------------------------------------------------
# Header parsing


class Comment:
    """A doxygen comment: blocks of ('p', text) paragraphs and ('li', text) list items."""

    def __init__(self, raw):
        self.blocks = []
        current = None
        for line in raw.split("\n"):
            line = re.sub(r"^\s*\*(?!/) ?", "", line.rstrip())
            stripped = line.strip()
            indent = len(line) - len(line.lstrip())
            if not stripped:
                current = None
                continue
            if stripped.startswith("- "):
                current = ["li", stripped[2:], indent]
                self.blocks.append(current)
                continue
            if current is not None and current[0] == "li" and indent <= current[2]:
                current = None  # a paragraph right after a list
            if current is None:
                current = ["p", stripped, indent]
                self.blocks.append(current)
            else:
                current[1] += " " + stripped
        self.blocks = [b[:2] for b in self.blocks]
        for block in self.blocks:
            block[1] = re.sub(r"@p\s+", "", re.sub(r"\s+", " ", block[1])).strip()

    def text(self):
        return " ".join(b[1] for b in self.blocks)

    def around_item(self, setter):
        """(paragraphs before the list holding setter's item, paragraphs after it)."""
        index = next((i for i, (kind, text) in enumerate(self.blocks) if kind == "li"
                      and re.match(r"`?%s\s*\(" % re.escape(setter), text)), None)
        if index is None:
            return "", ""
        start = index
        while start > 0 and self.blocks[start - 1][0] == "li":
            start -= 1
        end = index
        while end + 1 < len(self.blocks) and self.blocks[end + 1][0] == "li":
            end += 1
        before = " ".join(t for k, t in self.blocks[:start] if k == "p")
        after = " ".join(t for k, t in self.blocks[end + 1:] if k == "p")
        return before, after

    def list_naming(self, setter):
        """The items of the list that has an item naming setter() (e.g. in a class description)."""
        lists, current = [], []
        for kind, text in self.blocks:
            if kind == "li":
                current.append(text)
            elif current:
                lists.append(current)
                current = []
        if current:
            lists.append(current)
        for items in lists:
            if any(re.search(r"\b%s\s*\(" % re.escape(setter), t) for t in items):
                return items
        return None

    def item_for(self, setter):
        """The list item that documents setter (starts with 'SetName('), or None."""
        for kind, text in self.blocks:
            if kind == "li" and re.match(r"`?%s\s*\(" % re.escape(setter), text):
                return text
        return None


class Statement:
    def __init__(self, text, comment, line):
        self.text = re.sub(r"\s+", " ", text).strip()
        self.comment = comment
        self.line = line


def class_body(source, cls):
    m = re.search(r"\bclass\s+(?:\w+\s+)?%s\b[^;{]*\{" % cls, source)
    if not m:
        raise SystemExit("error: class %s not found in its header" % cls)
    depth, i = 1, m.end()
    while depth and i < len(source):
        depth += {"{": 1, "}": -1}.get(source[i], 0)
        i += 1
    return source[m.end():i - 1], source.count("\n", 0, m.end()) + 1


def public_sections(body, first_line):
    """(text, line of its start) of each public: region of the class body."""
    parts = re.split(r"^\s*(public|protected|private)\s*:", body, flags=re.M)
    out = []
    pos = len(parts[0])
    for i in range(1, len(parts), 2):
        access = parts[i]
        text = parts[i + 1]
        start = body.find(text, pos)
        pos = start + len(text)
        if access == "public":
            out.append((text, first_line + body.count("\n", 0, start)))
    return out


def statements(text, first_line):
    """Splits a public region into statements, each with the doxygen comment that applies."""
    result = []
    in_group = False
    group_comment = None
    group_started = False
    pending = None
    buf, buf_line = [], None
    depth = 0
    i, n = 0, len(text)

    def line_at(pos):
        return first_line + text.count("\n", 0, pos)

    def finish():
        nonlocal buf, buf_line, pending, group_started
        stmt = "".join(buf).strip()
        if stmt:
            comment = pending or (group_comment if in_group else None)
            result.append(Statement(stmt, comment, buf_line))
            pending = None
            group_started = True
        buf, buf_line = [], None

    while i < n:
        if text.startswith("///@{", i):
            in_group, group_comment, group_started, pending = True, None, False, None
            i += 5
            continue
        if text.startswith("///@}", i):
            in_group, group_comment, pending = False, None, None
            i += 5
            continue
        if text.startswith("/**", i) and not text.startswith("/**/", i):
            end = text.find("*/", i + 3)
            comment = Comment(text[i + 3:end])
            if depth == 0:
                if in_group and group_comment is None and not group_started:
                    group_comment = comment
                else:
                    pending = comment
            i = end + 2
            continue
        if text.startswith("///<", i) or text.startswith("//", i):
            if text.startswith("///", i) and not text.startswith("///<", i) and depth == 0:
                end = text.find("\n", i)
                end = n if end < 0 else end
                lines = [text[i + 3:end]]
                j = end + 1
                while True:
                    m = re.match(r"[ \t]*///(?![<@])([^\n]*)\n?", text[j:])
                    if not m:
                        break
                    lines.append(m.group(1))
                    j += m.end()
                comment = Comment("\n".join(lines))
                if in_group and group_comment is None and not group_started:
                    group_comment = comment
                else:
                    pending = comment
                i = j
                continue
            end = text.find("\n", i)
            i = n if end < 0 else end
            continue
        if text.startswith("/*", i):
            i = text.find("*/", i + 2) + 2
            continue
        c = text[i]
        if buf_line is None and not c.isspace():
            buf_line = line_at(i)
        buf.append(c)
        if c in "{(":
            depth += 1
        elif c in "})":
            depth -= 1
            if c == "}" and depth == 0:
                m = re.match(r"\s*;", text[i + 1:])
                if m:
                    buf.append(";")
                    i += 1 + m.end()
                    finish()
                    continue
                finish()
        elif c == ";" and depth == 0:
            finish()
        i += 1
    return result


def split_args(text):
    args, depth, cur = [], 0, []
    for c in text:
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        if c == "," and depth == 0:
            args.append("".join(cur).strip())
            cur = []
        else:
            cur.append(c)
    if "".join(cur).strip():
        args.append("".join(cur).strip())
    return args


def parse_enums(body):
    enums = []
    for m in re.finditer(r"\benum\s+(\w+)\s*\{(.*?)\}\s*;", body, re.S):
        entries, value = [], -1
        for line in m.group(2).split("\n"):
            e = re.match(r"\s*(\w+)\s*(?:=\s*([^,/]+?))?\s*,?\s*(?:///<\s*(.*))?$", line)
            if not e or not e.group(1):
                continue
            value = int(e.group(2), 0) if e.group(2) else value + 1
            entries.append((e.group(1), value, (e.group(3) or "").strip()))
        enums.append((m.group(1), entries))
    return enums


def parse_args(arglist):
    """[(type, name, array size)] of a C++ argument list."""
    out = []
    for arg in split_args(arglist):
        arg = re.sub(r"=.*$", "", arg).strip()
        if not arg or arg == "void":
            continue
        m = re.match(r"(.*?)(\w+)\s*(?:\[\s*(\d*)\s*\])?$", arg)
        typ = re.sub(r"\bconst\b", "", m.group(1)).strip()
        out.append((re.sub(r"\s+", " ", typ), m.group(2), m.group(3)))
    return out


METHOD = re.compile(
    r"^(?P<quals>(?:(?:virtual|static|inline)\s+)*)(?P<ret>[\w:<>]+(?:\s*\*)*)\s*(?P<name>\w+)\s*"
    r"\((?P<args>[^()]*)\)\s*(?:const\s*)?(?:override\s*)?(?:VTK_\w+\([^)]*\)\s*)?(?:=\s*0\s*)?"
    r"(?P<body>\{.*\})?\s*;?$")


class Header:
    """What one header declares: setters, getters, enums, keys and member initializers."""

    def __init__(self, cls, path):
        self.cls, self.path = cls, path
        with open(os.path.join(ROOT, path)) as f:
            source = f.read()
        body, body_line = class_body(source, cls)
        brief = re.search(r"@brief\s+(.*?)(?:\n\s*\*\s*\n|\*/)", source, re.S)
        self.brief = re.sub(r"\s*\n\s*\*?\s*", " ", brief.group(1)).strip() if brief else ""
        described = re.search(r"/\*\*((?:(?!\*/).)*?@class\s+%s\b.*?)\*/" % cls, source, re.S)
        self.description = Comment(described.group(1)) if described else None
        self.enums = parse_enums(body)
        self.initializers = {}
        for m in re.finditer(r"^\s*[\w:<>]+[\s\*]+(\w+)\s*(?:\[\s*\d+\s*\])?\s*=\s*([^;]+);",
                             body, re.M):
            self.initializers[m.group(1)] = m.group(2).strip()
        self.stmts = []
        for text, line in public_sections(body, body_line):
            self.stmts.extend(statements(text, line))

    def enum_of(self, identifiers):
        for name, entries in self.enums:
            names = {e[0] for e in entries}
            if identifiers and all(i in names for i in identifiers):
                return name, entries
        return None


# ------------------------------------------------------------------------------------------------
# The parameter model


class Param:
    def __init__(self, name, kind, comment, line):
        self.name = name
        self.kind = kind  # scalar, bool, enum, bitmask, string, object, vector, list, writeonly
        self.comment = comment
        self.line = line
        self.type = None
        self.size = 1
        self.clamp = None  # (lo expression, hi expression) of vtkSetClampMacro
        self.custom = False  # a hand-written setter (no macro)
        self.enum = None  # (name, entries)
        self.conveniences = []  # (method, own comment or None)
        self.setter = "Set" + name
        self.setter_args = []
        self.object_type = None
        self.default = None  # Python value
        self.default_text = ""
        self.range_text = ""
        self.unit = "—"
        self.meaning_full = ""
        self.meaning_short = ""
        self.shared_with = None
        self.per_actor = []
        self.range_numbers = None  # (lo, hi) when known (vectors: of each component)
        self.allowed_values = None  # the only values a snapping setter keeps, when it snaps
        self.header_path = None
        self.inherited = None  # (base class, in the project?, header) when inherited

    @property
    def doc(self):
        """The part of the comment about this parameter (its list item when it has one)."""
        if self.comment is None:
            return ""
        item = self.comment.item_for(self.setter)
        return item if item else self.comment.text()


def find_params(header, errors):
    params, order = {}, []
    getters = {}
    conveniences = []
    adders, removers = {}, set()
    actor_setters, actor_removers, keys = [], [], []
    nested = []
    class_names = {c for c, _ in CLASSES}

    def add(name, kind, stmt):
        if name in params:
            return params[name]
        p = Param(name, kind, stmt.comment, stmt.line)
        p.header_path = header.path
        params[name] = p
        order.append(name)
        return p

    for st in header.stmts:
        s = st.text
        m = re.match(r"^(vtk\w+Macro)\s*\((.*)\)\s*;?$", s)
        if m:
            macro, args = m.group(1), split_args(m.group(2))
            if macro == "vtkSetClampMacro":
                p = add(args[0], "scalar", st)
                p.type, p.clamp = args[1], (args[2], args[3])
            elif macro == "vtkSetMacro":
                p = add(args[0], "bool" if args[1] == "bool" else "scalar", st)
                p.type = args[1]
            elif macro == "vtkSetStringMacro":
                add(args[0], "string", st).type = "char*"
            elif macro in ("vtkSetObjectMacro", "vtkSetSmartPointerMacro"):
                p = add(args[0], "object", st)
                p.object_type = args[1]
            elif macro == "vtkSetEnumMacro":
                p = add(args[0], "enum", st)
                p.enum = next(((n, e) for n, e in header.enums if n == args[1]), None)
            elif re.match(r"vtkSetVector(\d)Macro$", macro):
                p = add(args[0], "vector", st)
                p.size, p.type = int(macro[12]), args[1]
            elif macro == "vtkSetVectorMacro":
                p = add(args[0], "vector", st)
                p.type, p.size = args[1], int(args[2])
            elif macro.startswith("vtkGet"):
                getters[args[0]] = macro
            continue
        m = METHOD.match(s)
        if not m:
            continue
        name, ret = m.group("name"), m.group("ret").replace(" ", "")
        static = "static" in m.group("quals")
        args = parse_args(m.group("args"))
        if static and ret.startswith("vtkInformation") and ret.endswith("Key*") and not args:
            keys.append((name, st.comment))
            continue
        if static and args and args[0][0] == "vtkProp*":
            if name.startswith("Set"):
                actor_setters.append((name, args[1:], st))
            elif name.startswith("Remove"):
                actor_removers.append((name, st))
            continue
        if static:
            continue
        if name.startswith("Get") and not args:
            getters.setdefault(name[3:], "method")
            base = ret.rstrip("*")
            if base in class_names and ret.endswith("*"):
                nested.append((name, base, st))
            continue
        if name.startswith("Get"):
            getters.setdefault(name[3:], "method")
            continue
        if ret != "void":
            continue
        if name.startswith("Add") and args:
            adders.setdefault(name[3:], (args, st))
            continue
        if name.startswith("RemoveAll"):
            removers.add(name[9:])
            continue
        if not name.startswith("Set"):
            continue
        prop = name[3:]
        if not args:
            conveniences.append((prop, name, st))
            continue
        if len(args) == 1 and args[0][2]:
            continue  # the array overload of a vector setter
        if prop in params:
            continue
        types = [a[0] for a in args]
        if len(args) == 1 and types[0].endswith("*") and types[0] not in ("char*",):
            p = add(prop, "object", st)
            p.object_type, p.custom = types[0].rstrip("*"), True
        elif len(args) == 1 and types[0] == "char*":
            p = add(prop, "string", st)
            p.custom = True
        elif all(t in SCALAR_TYPES for t in types):
            p = add(prop, "scalar" if len(args) == 1 else "vector", st)
            p.type, p.size, p.custom = types[0], len(args), True
            p.setter_args = args
        # other setters (e.g. of shader uniforms) are not parameters
    for prop, (args, st) in adders.items():
        if prop + "s" in removers or prop + "es" in removers:
            p = add(prop, "list", st)
            p.setter = "Add" + prop
            p.setter_args, p.size, p.type = args, len(args), args[0][0]
            p.custom = True
    # getters decide what a setter is: no getter, write-only; vector getter sizes the vector
    for name in list(order):
        p = params[name]
        g = getters.get(name)
        if p.kind == "list":
            continue
        if g is None:
            if p.kind in ("scalar", "vector") and p.custom:
                p.kind = "writeonly"
            elif p.kind in ("object", "string") and p.custom:
                del params[name]
                order.remove(name)
            continue
        gv = re.match(r"vtkGetVector(\d)Macro", g)
        if gv and p.kind == "scalar" and p.custom:
            p.kind = "vector"
        if gv:
            p.size = int(gv.group(1))
    for prop, method, st in conveniences:
        for name in order:
            if prop.startswith(name + "To"):
                params[name].conveniences.append((method, st.comment))
                break
    for name in order:
        p = params[name]
        if p.kind == "scalar" and p.clamp:
            lo, hi = p.clamp
            idents = [t for t in re.findall(r"[A-Za-z_]\w*", lo + " " + hi)
                      if not re.match(r"^(?:[0-9]|VTK_)", t)]
            found = header.enum_of(idents) if idents else None
            if found:
                p.enum = found
                p.kind = "bitmask" if "|" in hi else "enum"
        if p.comment is None:
            errors.append("%s:%d: %s::%s has no doc comment" % (header.path, p.line,
                                                                header.cls, name))
    return ([params[n] for n in order], actor_setters, actor_removers, keys, nested)


# ------------------------------------------------------------------------------------------------
# Values


def fmt_num(v):
    if isinstance(v, bool):
        return "on" if v else "off"
    if isinstance(v, int):
        return str(v)
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "NaN"
    if v != 0 and abs(v) >= 1e4:
        e = math.log10(abs(v))
        if abs(e - round(e)) < 1e-12:
            return ("-" if v < 0 else "") + "1e%d" % round(e)
    s = "%.6g" % v
    s = re.sub(r"e\+?(-?)0*(\d)", r"e\1\2", s)
    return s


def fmt_tuple(values):
    return "(" + ", ".join(fmt_num(v) for v in values) + ")"


BAD = object()  # what parse_value returns for text that is not a value


def parse_value(token):
    """A value written in a comment or an initializer, or BAD."""
    token = token.strip()
    if token in NAMED_VALUES:
        return NAMED_VALUES[token]
    if token in ("true", "false"):
        return token == "true"
    if re.fullmatch(r'"[^"]*"', token):
        return token[1:-1]
    m = re.fullmatch(r"(%s)\s*/\s*(%s)" % (NUM, NUM), token)
    if m:
        return float(m.group(1)) / float(m.group(2))
    if re.fullmatch(NUM, token):
        return float(token)
    m = re.fullmatch(r"\((.*)\)", token) or re.fullmatch(r"\{(.*)\}", token)
    if m:
        parts = [parse_value(t) for t in split_args(m.group(1))]
        return tuple(parts) if all(isinstance(x, (int, float)) for x in parts) else BAD
    if re.fullmatch(r"%s(?:\s*x\s*%s)+" % (NUM, NUM), token):
        return tuple(float(t) for t in re.split(r"\s*x\s*", token))
    if re.fullmatch(r"[A-Z][A-Z0-9_]+", token):
        return token  # an enum symbol
    return BAD


VALUE_TOKEN = re.compile(
    r'\((?:\s*%s\s*,)+\s*%s\s*\)|%s\s*/\s*%s|%s|"[^"]*"|\b(?:on|off|nullptr|NULL|white|black)\b|'
    r"\b[A-Z][A-Z0-9_]+\b" % (NUM, NUM, NUM, NUM, NUM))


def stated_defaults(text):
    """Defaults a comment states, in order: [(value, 'each' or '')]."""
    found, consumed = [], []
    # "SYMBOL (default)", "8 (...; default)", "VIEW (camera coordinates, the default)"
    for m in re.finditer(r"(\w+|\"[^\"]*\") \((?:[^()]*?[;,] )?(?:the )?default\b", text):
        v = parse_value(m.group(1))
        if v is BAD:
            continue
        found.append((m.start(), v, ""))
        consumed.append((m.start(), m.end()))
    # "(0 x 0, the default)"
    for m in re.finditer(r"\(([^()]*?),? the default\)", text):
        if any(a <= m.start() < b for a, b in consumed):
            continue
        v = parse_value(m.group(1))
        if v is not BAD:
            found.append((m.start(), v, ""))
            consumed.append((m.start(), m.end()))
    # "Default 4", "defaults 0.25 and 0.5", "Default: nullptr", "Default (0.8, 0.95)"
    for m in re.finditer(r"\b([Dd]efaults?|[Ii]nitial value is(?: an?)?)\b:?\s*", text):
        if any(a <= m.start() < b for a, b in consumed):
            continue
        pos = m.end()
        plural = m.group(1).lower() == "defaults"
        while True:
            t = VALUE_TOKEN.match(text, pos)
            if not t:
                break
            v = parse_value(t.group(0))
            if v is BAD:
                break
            pos = t.end()
            each = re.match(r"\s+each\b", text[pos:])
            if each:
                pos += each.end()
            found.append((m.start() + len(found) * 1e-3, v, "each" if each else ""))
            more = re.match(r"\s*(?:,|and)\s*", text[pos:]) if plural else None
            if not more or not VALUE_TOKEN.match(text, pos + more.end()):
                break
            pos += more.end()
    found.sort(key=lambda f: f[0])
    return [(v, e) for _, v, e in found]


def stated_ranges(text):
    """Ranges a comment states, in order: [(lo, hi)]; 'Range(s) [a, b] (and [c, d])' first."""
    out = []
    for m in re.finditer(r"\bRanges?\s*", text):
        pos = m.end()
        first = True
        while True:
            r = re.match(r"%s\[\s*(%s)\s*,\s*(%s)\s*\]" % (
                r"" if first else r"\s*(?:\(default[^)]*\)\s*)?(?:and|,)\s*", NUM, NUM),
                text[pos:])
            if not r:
                break
            out.append((float(r.group(1)), float(r.group(2))))
            pos += r.end()
            first = False
    if out:
        return out
    for m in re.finditer(r"\b(?:in|each|each in)\s+\[\s*(%s)\s*,\s*(%s)\s*\]" % (NUM, NUM),
                         text, re.I):
        out.append((float(m.group(1)), float(m.group(2))))
    return out


def stated_unit(text, patterns):
    for pattern, unit in patterns:
        if re.search(pattern, text):
            return unit
    return None


def same(a, b):
    if isinstance(a, (tuple, list)) or isinstance(b, (tuple, list)):
        if not (isinstance(a, (tuple, list)) and isinstance(b, (tuple, list))):
            return False
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if a is None or b is None:
        return a is b
    if isinstance(a, str) or isinstance(b, str):
        return a == b
    a, b = float(a), float(b)
    return a == b or abs(a - b) <= 1e-9 * max(1.0, abs(a), abs(b))


def first_sentence(text):
    depth = 0
    for i, c in enumerate(text):
        if c in "([":
            depth += 1
        elif c in ")]":
            depth = max(0, depth - 1)
        elif c in ".!?" and depth == 0:
            rest = text[i + 1:]
            if not rest.strip():
                return text
            if re.match(r"\s+[A-Z0-9`\"(]", rest) and not re.search(r"\b(?:e\.g|i\.e|eq|vs|etc)$",
                                                                 text[:i], re.I):
                return text[:i + 1]
    return text


def md_cell(text):
    return text.replace("|", "\\|").replace("\n", " ")


# ------------------------------------------------------------------------------------------------
# Reading the code through the wrapping


def import_vtkstylize(build):
    try:
        import vtkstylize
    except ImportError:
        for sub in ("lib", "python"):
            sys.path.insert(0, os.path.join(build, sub))
        try:
            import vtkstylize
        except ImportError as e:
            raise SystemExit("error: cannot import vtkstylize (%s); put the build's python folder "
                             "on PYTHONPATH or pass --build" % e)
    return vtkstylize


def as_python_default(p, value):
    if p.kind == "bool":
        return bool(value)
    if p.type in ("int", "vtkIdType", "long") and isinstance(value, float) and value.is_integer():
        return int(value)
    return value


def probe_scalar(cls, p):
    """Range of a hand-written scalar setter: set extremes and read them back."""
    is_int = p.type in ("int", "long", "vtkIdType")
    results = []
    for v in ((-INT_PROBE, INT_PROBE) if is_int else (-PROBE, PROBE)):
        o = cls()
        getattr(o, "Set" + p.name)(v)
        results.append(getattr(o, "Get" + p.name)())
    lo, hi = results
    if abs(lo) >= (INT_PROBE if is_int else PROBE) or abs(hi) >= (INT_PROBE if is_int else PROBE):
        return None, None
    values = None
    if is_int and hi - lo <= 64:
        seen = set()
        for v in range(int(lo), int(hi) + 1):
            o = cls()
            getattr(o, "Set" + p.name)(v)
            seen.add(getattr(o, "Get" + p.name)())
        if len(seen) < hi - lo + 1:
            values = sorted(seen)
    return (lo, hi), values


def probe_vector(cls, p):
    out = []
    for v in (-PROBE, PROBE):
        o = cls()
        getattr(o, "Set" + p.name)(*([v] * p.size))
        out.append(tuple(getattr(o, "Get" + p.name)()))
    lows, highs = out
    if any(abs(x) >= PROBE for x in lows + highs):
        return None
    if len(set(lows)) == 1 and len(set(highs)) == 1:
        return (lows[0], highs[0])
    return None


def probe_list_size(cls, p):
    o = cls()
    count = getattr(o, "GetNumberOf%ss" % p.name, None)
    if count is None:
        return None
    for _ in range(1000):
        getattr(o, p.setter)(*([0.5] * p.size))
    n = count()
    return n if n < 1000 else None


# ------------------------------------------------------------------------------------------------
# Building the descriptions


class ClassDoc:
    pass


def enum_symbol(p, value):
    for name, v, _ in p.enum[1]:
        if v == value:
            return name
    return str(value)


def find_header(name):
    """(path relative to ROOT or absolute, project?) of a class's header, or (None, False)."""
    for folder in PROJECT_HEADER_DIRS:
        path = os.path.join(folder, name + ".h")
        if os.path.exists(os.path.join(ROOT, path)):
            return path, True
    for folder in sorted(glob.glob(VTK_HEADER_GLOB), reverse=True):
        path = os.path.join(folder, name + ".h")
        if os.path.exists(path):
            return path, False
    return None, False


def describe_class(mod, cls, path, errors, warnings):
    klass = getattr(mod, cls)
    instance = klass()
    header = Header(cls, path)
    params, actor_setters, actor_removers, keys, nested = find_params(header, errors)
    # parameters inherited from base classes (project and VTK), up to vtkObject
    project_bases = []
    for base in klass.__mro__[1:]:
        name = base.__name__
        if name in FRAMEWORK_BASES:
            break
        base_path, project = find_header(name)
        if base_path is None:
            warnings.append("%s: header of the base class %s not found: its parameters are not "
                            "listed" % (path, name))
            continue
        if project:
            project_bases.append(name)
        base_header = Header(name, base_path)
        found = find_params(base_header, errors if project else warnings)
        known = {q.name for q in params}
        for q in found[0]:
            if q.name not in known:
                q.inherited = (name, project, base_path)
                params.append(q)
        known_nested = {m for m, _, _ in nested}
        nested.extend(n for n in found[4] if n[0] not in known_nested)
    doc = ClassDoc()
    doc.cls, doc.header, doc.params, doc.brief = cls, header, params, header.brief
    doc.project_bases = project_bases
    where = "%s::" % cls
    seen_comments = {}
    for p in list(params):
        if p.kind in ("writeonly",):
            continue
        needed = ["GetNumberOf%ss" % p.name] if p.kind == "list" else ["Get" + p.name]
        if p.clamp:
            needed += ["Get%sMinValue" % p.name, "Get%sMaxValue" % p.name]
        missing = [m for m in needed + [p.setter] if not hasattr(klass, m)]
        if missing:
            errors.append("%s:%d: %s%s: the built class has no %s (is the build older than "
                          "the header? rebuild)" % (p.header_path, p.line, where, p.name,
                                                    ", ".join(missing)))
            params.remove(p)
    for p in params:
        loc = "%s:%d: %s%s" % (p.header_path, p.line, where, p.name)
        text = p.doc
        # meaning
        if p.comment is not None and p.comment.item_for(p.setter) is None:
            key = id(p.comment)
            if key in seen_comments:
                p.shared_with = seen_comments[key]
            else:
                seen_comments[key] = p.name
        p.meaning_full = text or "(no doc comment)"
        if p.comment is not None and p.comment.item_for(p.setter) is not None:
            before, after = p.comment.around_item(p.setter)
            p.meaning_full = " ".join(t for t in (before, text, after) if t)
        p.meaning_short = first_sentence(text) if text else "(no doc comment)"
        if p.inherited:
            base, project, _ = p.inherited
            origin = "Inherited from `%s`%s" % (base, "" if project else " (VTK)")
            # prefer what the project says about it: a list naming the setter in the class
            # description of this class or of a project base class
            described = None
            for owner, owner_header in [(cls, header)] + [(b, Header(b, find_header(b)[0]))
                                                           for b in project_bases if b != base]:
                items = (owner_header.description.list_naming(p.setter)
                         if owner_header.description else None)
                if items:
                    described = (owner, items)
                    break
            if described:
                owner, items = described
                p.meaning_full = "%s; the class description of `%s`:<br>- %s" % (
                    origin, owner, "<br>- ".join(items))
                p.meaning_short = "%s; `%s`: %s" % (
                    origin, owner, " ".join(first_sentence(t) for t in items))
            else:
                p.meaning_full = "%s: %s" % (origin, p.meaning_full)
                p.meaning_short = "%s: %s" % (origin, p.meaning_short)
        # enum values must agree with the wrapping
        if p.enum:
            for name, value, _ in p.enum[1]:
                wrapped = getattr(klass, name, None)
                if isinstance(wrapped, int) and wrapped != value:
                    errors.append("%s: enum %s = %d in the header parse, %d in the wrapping"
                                  % (loc, name, value, wrapped))
        # default
        if p.kind == "writeonly":
            init = header.initializers.get(p.name)
            p.default = parse_value(init) if init is not None else BAD
            if p.default is BAD:
                p.default = None
                warnings.append("%s: no getter and no member initializer: default unknown" % loc)
        elif p.kind == "list":
            count = getattr(instance, "GetNumberOf%ss" % p.name, None)
            p.default = count() if count else None
        else:
            p.default = as_python_default(p, getattr(instance, "Get" + p.name)())
        # default text
        if p.kind in ("enum",):
            p.default_text = "`%s`" % enum_symbol(p, p.default)
        elif p.kind == "bitmask":
            bits = [n for n, v, _ in p.enum[1] if v and (p.default & v) == v]
            p.default_text = " \\| ".join("`%s`" % b for b in bits) if bits else "0 (none)"
        elif p.kind == "bool":
            p.default_text = "on" if p.default else "off"
        elif p.kind == "string":
            p.default_text = "none" if p.default is None else '`"%s"`' % p.default
        elif p.kind == "object":
            p.default_text = "none" if p.default is None else "`%s`" % p.default.GetClassName()
        elif p.kind == "list":
            p.default_text = "empty" if not p.default else "%d entries" % p.default
        elif p.kind in ("vector", "writeonly") and isinstance(p.default, tuple):
            p.default_text = fmt_tuple(p.default)
        elif p.default is None:
            p.default_text = "—"
        else:
            p.default_text = fmt_num(p.default)
        # unit
        if p.kind in ("scalar", "vector", "writeonly", "list"):
            patterns = VECTOR_UNIT_PATTERNS if p.kind in ("vector", "list") else UNIT_PATTERNS
            unit = stated_unit(text, patterns)
            if unit:
                p.unit = unit
            else:
                warnings.append("%s: the comment states no unit" % loc)
        # range
        ranges = stated_ranges(text)
        group = [q for q in params if q.comment is p.comment and p.comment is not None
                 and q.comment.item_for(q.setter) is None] if p.comment is not None else [p]
        if p.comment is not None and p.comment.item_for(p.setter) is not None:
            group = [p]
        stated = None
        if len(ranges) == 1:
            stated = ranges[0]
        elif ranges and len(ranges) == len(group) and p in group:
            stated = ranges[group.index(p)]
        if p.kind == "scalar" and p.clamp:
            lo = getattr(instance, "Get%sMinValue" % p.name)()
            hi = getattr(instance, "Get%sMaxValue" % p.name)()
            p.range_numbers = (lo, hi)
            p.range_text = "[%s, %s]" % (fmt_num(lo), fmt_num(hi))
            if stated and not (same(stated[0], lo) and same(stated[1], hi)):
                errors.append("%s: the comment states the range [%s, %s], the code clamps to "
                              "[%s, %s]" % (loc, fmt_num(stated[0]), fmt_num(stated[1]),
                                            fmt_num(lo), fmt_num(hi)))
            if not ranges:
                warnings.append("%s: the comment states no range (code: %s)" % (loc,
                                                                               p.range_text))
        elif p.kind in ("enum", "bitmask"):
            lo = getattr(instance, "Get%sMinValue" % p.name, lambda: None)()
            hi = getattr(instance, "Get%sMaxValue" % p.name, lambda: None)()
            entries = [e for e in p.enum[1] if p.kind == "bitmask" or lo is None
                       or lo <= e[1] <= hi]
            p.range_text = ", ".join("`%s`=%d" % (n, v) for n, v, _ in entries)
            if p.kind == "bitmask":
                p.range_text = "any OR of " + p.range_text
                if hi is not None:
                    p.range_text += " ([%s, %s])" % (fmt_num(lo), fmt_num(hi))
            p.enum_entries = entries
        elif p.kind == "bool":
            p.range_text = "on/off"
        elif p.kind == "string":
            p.range_text = "text"
        elif p.kind == "object":
            p.range_text = "`%s` or none" % p.object_type
        elif p.kind == "scalar":  # hand-written setter or vtkSetMacro without clamping
            probed, values = probe_scalar(klass, p) if p.custom else ((None, None), None)
            if values:
                p.range_text = ", ".join(fmt_num(v) for v in values) + " (others are snapped)"
                p.range_numbers = (values[0], values[-1])
                p.allowed_values = values
                stated_values = [float(x) for x in re.findall(NUM, text)]
                if not all(any(same(v, s) for s in stated_values) for v in values):
                    warnings.append("%s: the comment does not list the values %s" % (
                        loc, p.range_text))
            elif probed and probed[0] is not None:
                p.range_numbers = probed
                p.range_text = "[%s, %s]" % (fmt_num(probed[0]), fmt_num(probed[1]))
                if stated and not (same(stated[0], probed[0]) and same(stated[1], probed[1])):
                    errors.append("%s: the comment states the range [%s, %s], the setter "
                                  "clamps to %s" % (loc, fmt_num(stated[0]), fmt_num(stated[1]),
                                                    p.range_text))
            elif stated:
                p.range_text = "[%s, %s]" % (fmt_num(stated[0]), fmt_num(stated[1]))
                p.range_numbers = stated
            else:
                p.range_text = "—"
                warnings.append("%s: the comment states no range" % loc)
        elif p.kind in ("vector", "list", "writeonly"):
            each = "each " if p.size > 1 else ""
            if stated:
                p.range_text = "%s[%s, %s]" % (each, fmt_num(stated[0]), fmt_num(stated[1]))
                p.range_numbers = stated
            else:
                p.range_text = "—"
                warnings.append("%s: the comment states no range" % loc)
            if p.kind == "vector":
                probed = probe_vector(klass, p)
                if stated and probed and not (same(stated[0], probed[0])
                                              and same(stated[1], probed[1])):
                    errors.append("%s: the comment states %s, the setter clamps each component "
                                  "to [%s, %s]" % (loc, p.range_text, fmt_num(probed[0]),
                                                   fmt_num(probed[1])))
                if not stated and probed:
                    p.range_text = "each [%s, %s]" % (fmt_num(probed[0]), fmt_num(probed[1]))
                    p.range_numbers = probed
            if p.kind == "list":
                most = probe_list_size(klass, p)
                m = re.search(r"\bat most (\d+)", text)
                if most is not None:
                    p.range_text += ", at most %d entries" % most
                    if m and int(m.group(1)) != most:
                        errors.append("%s: the comment says at most %s, the code keeps %d"
                                      % (loc, m.group(1), most))
        # the comment's own default must agree with the code
        defaults = stated_defaults(text)
        mine = None
        if len(group) > 1 and len(defaults) == len(group):
            mine = defaults[group.index(p)]
        elif len(defaults) == 1 or (defaults and len(group) == 1):
            mine = defaults[0]
        if not defaults:
            warnings.append("%s: the comment states no default (code: %s)" % (loc,
                                                                            p.default_text))
        elif mine is None:
            warnings.append("%s: cannot tell which of the comment's defaults is this one's" % loc)
        else:
            value, each = mine
            code = p.default
            if isinstance(value, str) and p.enum:
                value = next((v for n, v, _ in p.enum[1] if n == value), value)
            if each and isinstance(code, tuple):
                value = tuple([value] * len(code))
            if p.kind == "object" and code is not None:
                code = "set"
            if not same(value, code):
                shown = value if not isinstance(value, tuple) else fmt_tuple(value)
                if isinstance(shown, float):
                    shown = fmt_num(shown)
                errors.append("%s: the comment states the default %s, the code has %s" % (
                    loc, shown, p.default_text))
    # per-actor settings (static setters taking a vtkProp)
    doc.actor = []
    if actor_setters:
        from vtkmodules.vtkRenderingCore import vtkActor
        key_objects = [(k, getattr(klass, k)()) for k, _ in keys]
        by_name = {p.name: p for p in params}
        for method, args, st in actor_setters:
            results = {}
            for v in (-PROBE, PROBE):
                actor = vtkActor()
                getattr(klass, method)(actor, *([v] * len(args)))
                info = actor.GetPropertyKeys()
                for kname, key in key_objects:
                    if info is not None and info.Has(key):
                        results.setdefault(kname, []).append(info.Get(key))
            rows = []
            for kname, (lo, hi) in results.items():
                prop = "".join(w.capitalize() for w in kname.lower().split("_"))
                target = by_name.get(prop)
                rng = "[%s, %s]" % (fmt_num(lo), fmt_num(hi))
                if target is not None and target.range_numbers and not (
                        same(target.range_numbers[0], lo) and same(target.range_numbers[1], hi)):
                    errors.append("%s:%d: %s clamps %s to %s, the pass's %s to %s" % (
                        path, st.line, method, kname, rng, prop, target.range_text))
                if target is not None:
                    target.per_actor.append("`%s()`" % kname)
                rows.append((kname, prop if target is not None else None, rng))
            if not rows:
                warnings.append("%s:%d: %s%s sets none of the keys %s" % (
                    path, st.line, where, method, ", ".join(k for k, _ in keys)))
            if st.comment is None:
                errors.append("%s:%d: %s%s has no doc comment" % (path, st.line, where, method))
            signature = "%s(prop, %s)" % (method, ", ".join(a[1] for a in args))
            doc.actor.append((signature, rows, st.comment.text() if st.comment else ""))
        doc.actor_removers = [("%s(prop)" % m, st.comment.text() if st.comment else "")
                              for m, st in actor_removers]
        doc.keys = [(k, c.text() if c else "") for k, c in keys]
    # nested passes of a style, and where their defaults differ from a standalone instance
    doc.nested = []
    for method, base, st in nested:
        doc.nested.append((method, base, st.comment.text() if st.comment else ""))
    doc.klass = klass
    return doc


def nested_differences(doc, docs_by_class):
    out = []
    instance = doc.klass()
    for method, base, comment in doc.nested:
        child = getattr(instance, method)()
        ref = docs_by_class.get(base)
        if child is None or ref is None:
            continue
        diffs = []
        for p in ref.params:
            if p.kind in ("writeonly", "list"):
                continue
            value = as_python_default(p, getattr(child, "Get" + p.name)())
            if p.kind == "object":
                if (value is None) != (p.default is None):
                    owner = None
                    for m2, _, _ in doc.nested:
                        other = getattr(instance, m2)()
                        if value is not None and other is not None and \
                                value.GetAddressAsString("vtkObject") == \
                                other.GetAddressAsString("vtkObject"):
                            owner = m2
                    shown = "this pass's `%s()`" % owner if owner else (
                        "none" if value is None else "a `%s`" % value.GetClassName())
                    diffs.append("`%s` = %s" % (p.name, shown))
                continue
            if same(value, p.default):
                continue
            if p.kind == "enum":
                shown = "`%s`" % enum_symbol(p, value)
            elif p.kind == "bool":
                shown = "on" if value else "off"
            elif isinstance(value, tuple):
                shown = fmt_tuple(value)
            else:
                shown = fmt_num(value)
            diffs.append("`%s` = %s (standalone: %s)" % (p.name, shown, p.default_text))
        out.append((method, base, diffs))
    return out


# ------------------------------------------------------------------------------------------------
# Output


def anchor(cls):
    return cls.lower()


def render_parameters(docs):
    docs_by_class = {d.cls: d for d in docs}
    L = []
    L.append("# Parameters")
    L.append("")
    L.append("<!-- Generated by scripts/parameters.py from the headers in Passes/ and the built "
             "classes. Do not edit: run `/usr/bin/python3 scripts/parameters.py`. -->")
    L.append("")
    L.append("Every user-settable parameter of the passes, generated by `scripts/parameters.py` "
             "so that it cannot drift from the code; `ctest -R docs.parameters` fails when this "
             "file or the README's parameter tables are out of date, when a parameter has no "
             "doc comment, or when a comment states a range or default the code does not have.")
    L.append("")
    L.append("- **parameter**: the VTK property, set with `Set<Name>()` and read with "
             "`Get<Name>()` (booleans also `<Name>On()`/`<Name>Off()`).")
    L.append("- **meaning**: the doc comment above the setter in the header.")
    L.append("- **unit**: as the comment states it (— where it states none; points are pixels "
             "of an image `ReferenceHeight` pixels tall).")
    L.append("- **range**: for clamped settings `Get<Name>MinValue()`/`Get<Name>MaxValue()`; for "
             "enumerations the symbolic values (class constants, e.g. "
             "`vtkComicPass.OBJECT`); for other setters the range the comment states, checked "
             "by setting out-of-range values and reading them back. Setters clamp: out-of-range "
             "values take the nearest bound.")
    L.append("- **default**: `Get<Name>()` of a new instance (setters without a getter: the "
             "member's initializer in the header).")
    L.append("")
    L.append("Classes: " + ", ".join("[`%s`](#%s)" % (d.cls, anchor(d.cls)) for d in docs) + ".")
    for d in docs:
        L.append("")
        L.append("## %s" % d.cls)
        L.append("")
        L.append("%s (`%s`)" % (d.brief, d.header.path))
        L.append("")
        L.append("| parameter | unit | range | default | meaning |")
        L.append("|---|---|---|---|---|")
        for p in d.params:
            name = "`%s`" % p.name
            if p.kind == "list":
                name = "`%s()`" % p.setter
            elif p.kind == "writeonly":
                name = "`%s(%s)` (no getter)" % (p.setter, ", ".join(a[1] for a in p.setter_args))
            if p.shared_with:
                meaning = "See `%s`." % p.shared_with
            else:
                meaning = p.meaning_full
            extra = []
            if p.enum and p.kind in ("enum", "bitmask"):
                extra.extend("`%s` (%d): %s" % (n, v, doc) if doc else "`%s` (%d)" % (n, v)
                             for n, v, doc in getattr(p, "enum_entries", p.enum[1]))
            for method, comment in p.conveniences:
                own = comment.text() if comment is not None and comment is not p.comment else ""
                extra.append("`%s()`%s" % (method, ": " + own if own else ""))
            if p.per_actor:
                extra.append("Per actor: %s" % ", ".join(p.per_actor))
            if extra:
                meaning += "<br>" + "<br>".join(extra)
            L.append("| %s | %s | %s | %s | %s |" % (
                name, md_cell(p.unit), md_cell(p.range_text), md_cell(p.default_text),
                md_cell(meaning)))
        if d.actor:
            L.append("")
            L.append("### Per-actor settings of %s" % d.cls)
            L.append("")
            L.append("Static helpers that store a value in the prop's "
                     "`vtkProp::GetPropertyKeys()`; an actor with a key uses it instead of the "
                     "pass's setting. Range: found by setting out-of-range values and reading "
                     "the key back. Default: no key (the pass's value).")
            L.append("")
            L.append("| static setter | key | overrides | range |")
            L.append("|---|---|---|---|")
            for signature, rows, comment in d.actor:
                for i, (key, prop, rng) in enumerate(rows):
                    L.append("| %s | `%s()` | %s | %s |" % (
                        "`%s`" % signature if i == 0 else "", key,
                        "`%s`" % prop if prop else "—", rng))
            comments = []
            for signature, rows, comment in d.actor:
                if comment and comment not in comments:
                    comments.append(comment)
            for comment in comments:
                L.append("")
                L.append("Setters: %s" % comment)
            for m, comment in d.actor_removers:
                L.append("")
                L.append("Removed with `%s`%s" % (
                    m, "." if not comment or comment in comments else ": " + comment))
            key_comments = []
            for k, c in d.keys:
                if c and c not in key_comments:
                    key_comments.append(c)
            for c in key_comments:
                L.append("")
                L.append("Keys (%s): %s" % (", ".join("`%s()`" % k for k, _ in d.keys), c))
        diffs = nested_differences(d, docs_by_class)
        if diffs:
            L.append("")
            L.append("### Passes inside %s" % d.cls)
            L.append("")
            for method, base, changes in diffs:
                what = "; ".join(changes) if changes else "the standalone defaults"
                L.append("- `%s()`: a [`%s`](#%s) with %s." % (method, base, anchor(base), what))
    L.append("")
    return "\n".join(L)


def render_readme_block(d):
    L = []
    L.append("Generated by `scripts/parameters.py` from the header and the code (full comments, "
             "per-value notes: [docs/PARAMETERS.md](docs/PARAMETERS.md#%s)):" % anchor(d.cls))
    L.append("")
    per_actor = any(p.per_actor for p in d.params)
    head = "| setting | meaning | unit | range | default |"
    sep = "|---|---|---|---|---|"
    if per_actor:
        head += " per actor |"
        sep += "---|"
    L.append(head)
    L.append(sep)
    for p in d.params:
        name = "`%s()`" % p.setter if p.kind == "list" else "`%s`" % p.name
        meaning = "see `%s`" % p.shared_with if p.shared_with else p.meaning_short
        rng = p.range_text
        if p.kind in ("enum",):
            rng = ", ".join("`%s`" % n for n, _, _ in p.enum_entries)
        elif p.kind == "bitmask":
            rng = "OR of " + ", ".join("`%s`" % n for n, _, _ in p.enum_entries)
        row = "| %s | %s | %s | %s | %s |" % (name, md_cell(meaning), md_cell(p.unit),
                                              md_cell(rng), md_cell(p.default_text))
        if per_actor:
            row += " %s |" % (", ".join(p.per_actor) if p.per_actor else "-")
        L.append(row)
    return "\n".join(L)


BLOCK = re.compile(r"(<!-- parameters:(\w+) begin -->\n)(.*?)(<!-- parameters:\2 end -->)", re.S)


def render_readme(text, docs, errors):
    by_class = {d.cls: d for d in docs}

    def replace(m):
        d = by_class.get(m.group(2))
        if d is None:
            errors.append("%s: parameters block for unknown class %s" % (README, m.group(2)))
            return m.group(0)
        return m.group(1) + render_readme_block(d) + "\n" + m.group(4)

    out = BLOCK.sub(replace, text)
    # a hand-written parameter table outside the generated blocks could drift: refuse it
    names = {p.name for d in docs for p in d.params}
    outside = BLOCK.sub(lambda m: "\n" * m.group(0).count("\n"), out)
    in_fence = False
    for number, line in enumerate(outside.split("\n"), 1):
        if line.startswith("```"):
            in_fence = not in_fence
        if in_fence or not line.startswith("|"):
            continue
        first = line.split("|")[1] if line.count("|") > 1 else ""
        hits = [t for t in re.findall(r"`(\w+)`", first) if t in names]
        if hits:
            errors.append("%s:%d: hand-written parameter table row (%s) outside the generated "
                          "<!-- parameters:CLASS --> blocks" % (README, number, ", ".join(hits)))
    return out


# ------------------------------------------------------------------------------------------------
# ParaView server-manager XML (the plugin's view exposes these proxies as subproxies)


XML_PASSES = "Plugin/View/StylizePasses.xml"
XML_VIEW = "Plugin/View/StylizeView.xml"
XML_GROUP = "stylize_passes"
# (proxy name, class, label, exposed-name prefix, values of the view's Style that show it; None:
# every style, no decorator)
XML_PROXIES = [
    ("ComicPass", "vtkComicPass", "Comic", "Comic", "1"),
    ("PixelArtPass", "vtkPixelArtPass", "Pixel art", "PixelArt", "2"),
    ("SketchPass", "vtkSketchPass", "Sketch", "Sketch", "3"),
    ("LightingPass", "vtkStylizeLightingPass", "Lighting", "Lighting", None),
]
XML_ALL_STYLES = "1 2 3"
# Parameters the view sets itself, so not exposed: (class, parameter) -> why.
XML_SKIP = {("vtkStylizeLightingPass", "Model"): "set by the view"}
# panel_visibility="advanced": tuning knobs of the algorithms rather than of the look, by name,
# and settings whose comment says they are for measurement, testing or a baseline.
XML_ADVANCED_NAME = re.compile(r"(?:Thresholds?|Tolerance|Stride|Seed)$|^ReferenceHeight$")
XML_ADVANCED_TEXT = re.compile(
    r"\b(?:measurements?|testing|numeric tests?|baseline|accuracy study)\b", re.I)
XML_ADVANCED_RULE = (
    'panel_visibility="advanced" marks the tuning parameters: names ending in Threshold(s), '
    "Tolerance, Stride or Seed, the ReferenceHeight (the size of a point), and parameters whose "
    "comment says they are for measurement, testing or a baseline (e.g. the accuracy study's "
    "screen-space LIC).")
XML_INT_TYPES = {"int", "bool", "unsigned int", "long", "vtkIdType", "unsigned char", "char"}
XML_WIDTH = 100


def xml_text(text):
    return escape(text)


def xml_attr(text):
    return escape(str(text), {'"': "&quot;"})


def xml_num(v, loc, errors):
    """A number as ParaView reads it (istringstream): no inf/nan; integral values without '.0'."""
    if isinstance(v, bool):
        return "1" if v else "0"
    if isinstance(v, int):
        return str(v)
    v = float(v)
    if math.isnan(v) or math.isinf(v):
        errors.append("%s: %r cannot be written in the ParaView XML" % (loc, v))
        return "0"
    if v.is_integer() and abs(v) < 1e15:
        return str(int(v))
    return repr(v)


def readable_enum(symbol):
    """PALETTE16 -> 'Palette 16', SCREEN_2D -> 'Screen 2D', NO_EDGES -> 'No edges'."""
    words = []
    for part in symbol.split("_"):
        words.extend(w for w in re.split(r"(?<=[A-Za-z])(?=\d)", part) if w)
    out = []
    for i, w in enumerate(words):
        if re.search(r"\d", w):
            out.append(w)
        else:
            out.append(w.capitalize() if i == 0 else w.lower())
    return " ".join(out)


def plain(text):
    """Doc text for a tooltip: no markdown, normalized whitespace."""
    text = text.replace("<br>", " ").replace("`", "").replace("\\|", "|")
    return re.sub(r"\s+", " ", text).strip()


def xml_kind(p):
    """How a parameter is exposed: 'bool', 'enum', 'int', 'double', 'string', or None."""
    if p.kind in ("object", "list"):
        return None
    if p.kind == "bool":
        return "bool"
    if p.kind in ("enum", "bitmask"):
        return "enum" if p.kind == "enum" else "int"
    if p.kind == "string":
        return "string"
    types = [a[0] for a in p.setter_args] if p.setter_args else [p.type]
    if all(t in XML_INT_TYPES for t in types):
        if p.kind == "scalar" and p.range_numbers and tuple(p.range_numbers) == (0, 1) and \
                re.search(r"\bon/off\b|\bon\b.*\boff\b|\boff\b.*\bon\b", p.doc):
            return "bool"
        return "int"
    return "double"


def xml_skip_reason(cls, p):
    if (cls, p.name) in XML_SKIP:
        return XML_SKIP[(cls, p.name)]
    if p.kind == "object":
        return "object-valued, a %s" % p.object_type
    if p.kind == "list":
        return "list-valued, %s()/RemoveAll%ss()" % (p.setter, p.name)
    if p.kind == "writeonly" and p.default is None:
        return "no getter and no known default"
    return None


def xml_documentation(p, kind):
    parts = [plain(p.meaning_full)]
    if kind == "enum" and p.kind == "enum":
        entries = [(readable_enum(n), plain(d)) for n, _, d in p.enum_entries]
        if any(d for _, d in entries):
            parts.append(" ".join("%s: %s." % (t, d.rstrip(".")) if d else "%s." % t
                                  for t, d in entries))
        parts.append("Default %s." % readable_enum(enum_symbol(p, p.default)))
    elif kind == "bool":
        parts.append("On/off, default %s." % ("on" if p.default else "off"))
    elif kind == "string":
        parts.append('Text, default "%s".' % (p.default or ""))
    else:
        unit = "Unit: %s. " % p.unit if p.unit not in ("—", "") else ""
        default = plain(p.default_text)
        rng = plain(p.range_text)
        if p.allowed_values:
            sentence = "Values %s, default %s." % (rng, default)
        elif rng and rng != "—":
            if rng.startswith("each "):
                rng = rng[5:] + " each"
            sentence = "Range %s, default %s." % (rng, default)
        else:
            sentence = "Default %s." % default
        parts.append(unit + sentence)
    return " ".join(t for t in parts if t)


def wrap_xml_text(text, indent):
    lines = textwrap.wrap(text, XML_WIDTH - len(indent), break_long_words=False,
                          break_on_hyphens=False)
    # a line starting with "- " or "* " could read as a list in ParaView's rst-to-html
    out = []
    for line in lines:
        if out and re.match(r"[-*+] ", line):
            out[-1] += " " + line
        else:
            out.append(line)
    return "\n".join(indent + line for line in out)


def xml_open(tag, attrs, indent, close=">"):
    """An element's start tag; attributes past the line width go on indented continuation lines."""
    items = ['%s="%s"' % (k, xml_attr(v)) for k, v in attrs]
    line = "%s<%s %s%s" % (indent, tag, " ".join(items), close)
    if len(line) <= XML_WIDTH:
        return [line]
    lines = ["%s<%s %s" % (indent, tag, items[0])]
    for i, item in enumerate(items[1:], 2):
        tail = len(close) if i == len(items) else 0
        if len(lines[-1]) + 1 + len(item) + tail <= XML_WIDTH:
            lines[-1] += " " + item
        else:
            lines.append(indent + "    " + item)
    lines[-1] += close
    return lines


def xml_advanced(p):
    return bool(XML_ADVANCED_NAME.search(p.name) or XML_ADVANCED_TEXT.search(p.doc))


def xml_property(d, p, errors):
    """The lines of one property element, or None with the reason it is not exposed."""
    loc = "%s:%d: %s::%s" % (p.header_path, p.line, d.cls, p.name)
    kind = xml_kind(p)
    size = p.size if p.kind in ("vector", "writeonly") else 1
    element = {"bool": "IntVectorProperty", "enum": "IntVectorProperty",
               "int": "IntVectorProperty", "double": "DoubleVectorProperty",
               "string": "StringVectorProperty"}[kind]
    default = p.default
    if kind == "string":
        defaults = "" if default is None else default
    else:
        values = default if isinstance(default, (tuple, list)) else (default,)
        if len(values) != size:
            errors.append("%s: %d default values for %d elements" % (loc, len(values), size))
        if kind in ("bool", "enum", "int"):
            values = [int(v) for v in values]
        defaults = " ".join(xml_num(v, loc, errors) for v in values)
    attrs = [("name", p.name), ("command", p.setter), ("number_of_elements", str(size)),
             ("default_values", defaults)]
    if xml_advanced(p):
        attrs.append(("panel_visibility", "advanced"))
    is_color = (kind == "double" and size == 3
                and (re.search(r"Colou?r$", p.name) or p.unit == "RGB"))
    if is_color:
        attrs.append(("panel_widget", "color_selector"))
    L = xml_open(element, attrs, "      ")
    if kind == "bool":
        L.append('        <BooleanDomain name="bool"/>')
    elif kind == "enum" or (kind == "int" and p.allowed_values):
        L.append('        <EnumerationDomain name="enum">')
        if kind == "enum":
            entries = [(v, readable_enum(n)) for n, v, _ in p.enum_entries]
        else:
            entries = [(int(v), fmt_num(v)) for v in p.allowed_values]
        for value, text in entries:
            L.append('          <Entry value="%d" text="%s"/>' % (value, xml_attr(text)))
        L.append("        </EnumerationDomain>")
    elif kind in ("int", "double"):
        rng = p.range_numbers
        if p.kind == "bitmask":
            instance = d.klass()
            rng = (getattr(instance, "Get%sMinValue" % p.name)(),
                   getattr(instance, "Get%sMaxValue" % p.name)())
        if rng is not None:
            lo = " ".join([xml_num(int(rng[0]) if kind == "int" else rng[0], loc, errors)] * size)
            hi = " ".join([xml_num(int(rng[1]) if kind == "int" else rng[1], loc, errors)] * size)
            L.append('        <%sRangeDomain name="range" min="%s" max="%s"/>' % (
                "Int" if kind == "int" else "Double", lo, hi))
    L.append("        <Documentation>")
    L.append(wrap_xml_text(xml_text(xml_documentation(p, kind)), "          "))
    L.append("        </Documentation>")
    L.append("      </%s>" % element)
    return L


def xml_exposed(docs_by_class, errors):
    """{proxy name: [(parameter, lines)]} and {proxy name: [(parameter, why skipped)]}."""
    exposed, skipped = {}, {}
    for name, cls, _, _, _ in XML_PROXIES:
        d = docs_by_class[cls]
        exposed[name], skipped[name] = [], []
        for p in d.params:
            why = xml_skip_reason(cls, p)
            if why:
                skipped[name].append((p, why))
            else:
                exposed[name].append((p, xml_property(d, p, errors)))
    return exposed, skipped


def render_xml_passes(docs_by_class, exposed, skipped):
    L = ["<!--",
         "  Generated by scripts/parameters.py from the headers in Passes/ and the built classes;",
         "  do not edit by hand: run /usr/bin/python3 scripts/parameters.py (ctest -R",
         "  docs.parameters fails when this file is out of date).",
         "",
         "  One proxy per pass, one property per user parameter of the class (docs/PARAMETERS.md).",
         "  Defaults: Get<Name>() of a new instance; ranges and units as in docs/PARAMETERS.md.",
         ""]
    L.extend("  " + line for line in textwrap.wrap(XML_ADVANCED_RULE, XML_WIDTH - 2))
    L.append("-->")
    L.append("<ServerManagerConfiguration>")
    L.append('  <ProxyGroup name="%s">' % XML_GROUP)
    for name, cls, label, _, _ in XML_PROXIES:
        L.append('    <Proxy name="%s" class="%s" label="%s">' % (name, cls, xml_attr(label)))
        brief = plain(docs_by_class[cls].brief)
        if brief:
            L.append("      <Documentation>")
            L.append(wrap_xml_text(xml_text(brief), "        "))
            L.append("      </Documentation>")
        if skipped[name]:
            note = "not exposed: " + "; ".join("%s (%s)" % (p.name, why)
                                               for p, why in skipped[name])
            L.append("      <!--")
            L.append(wrap_xml_text(note.replace("--", "-"), "        "))
            L.append("      -->")
        for _, lines in exposed[name]:
            L.extend(lines)
        L.append("    </Proxy>")
    L.append("  </ProxyGroup>")
    L.append("</ServerManagerConfiguration>")
    L.append("")
    return "\n".join(L)


XML_VIEW_BLOCK = re.compile(
    r"([ \t]*<!-- generated:exposed:(\w+) begin -->\n)(.*?)([ \t]*<!-- generated:exposed:\2 end -->)",
    re.S)


def render_xml_view(view_xml, exposed, errors):
    """The view's XML with each subproxy's <ExposedProperties> rewritten between its markers."""
    proxies = {name: (label, prefix, style) for name, _, label, prefix, style in XML_PROXIES}
    seen = set()

    def block(m):
        name = m.group(2)
        if name not in proxies:
            errors.append("%s: unknown subproxy %s in a generated block" % (XML_VIEW, name))
            return m.group(0)
        seen.add(name)
        label, prefix, style = proxies[name]
        indent = m.group(1)[: len(m.group(1)) - len(m.group(1).lstrip())]
        L = ["<ExposedProperties>", '  <PropertyGroup label="%s">' % xml_attr(label)]
        for p, _ in exposed[name]:
            L.append('    <Property name="%s" exposed_name="%s%s" />' % (p.name, prefix, p.name))
        if style:
            L.append('    <Hints><PropertyWidgetDecorator type="GenericDecorator" '
                     'mode="visibility" property="Style" value="%s" /></Hints>' % style)
        L.append("  </PropertyGroup>")
        L.append("</ExposedProperties>")
        return m.group(1) + "".join(indent + line + "\n" for line in L) + m.group(4)

    out = XML_VIEW_BLOCK.sub(block, view_xml)
    for name in proxies:
        if name not in seen:
            errors.append("%s: no <!-- generated:exposed:%s begin/end --> markers" % (XML_VIEW, name))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true",
                        help="verify docs/PARAMETERS.md, the README tables and the ParaView XML "
                             "in Plugin/View/; write nothing")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"),
                        help="build folder whose python/ and lib/ hold vtkstylize (used when the "
                             "import fails)")
    parser.add_argument("--quiet", action="store_true", help="do not print warnings")
    args = parser.parse_args()

    mod = import_vtkstylize(args.build)
    from vtkmodules.vtkCommonCore import vtkObject
    vtkObject.GlobalWarningDisplayOff()  # probing out-of-range values makes setters warn
    errors, warnings = [], []
    docs = [describe_class(mod, cls, path, errors, warnings) for cls, path in CLASSES]
    generated = render_parameters(docs)
    readme_path = os.path.join(ROOT, README)
    with open(readme_path) as f:
        readme = f.read()
    new_readme = render_readme(readme, docs, errors)
    if not BLOCK.search(readme):
        warnings.append("%s: no <!-- parameters:CLASS begin --> blocks" % README)

    exposed, skipped = xml_exposed({d.cls: d for d in docs}, errors)
    xml_passes = render_xml_passes({d.cls: d for d in docs}, exposed, skipped)
    with open(os.path.join(ROOT, XML_VIEW)) as f:
        xml_view = render_xml_view(f.read(), exposed, errors)

    if not args.quiet:
        for w in warnings:
            print("warning: " + w)
    outputs = [(OUTPUT, generated), (README, new_readme), (XML_PASSES, xml_passes),
               (XML_VIEW, xml_view)]
    stale = []
    for path, new in outputs:
        full = os.path.join(ROOT, path)
        old = open(full).read() if os.path.exists(full) else None
        if old == new:
            continue
        stale.append(path)
        if args.check:
            if old is None:
                print("error: %s is missing" % path)
                continue
            diff = list(difflib.unified_diff(old.splitlines(True), new.splitlines(True),
                                             "a/" + path, "b/" + path))
            sys.stdout.writelines(diff[:DIFF_LINES])
            if len(diff) > DIFF_LINES:
                print("... (%d more lines of diff in %s)" % (len(diff) - DIFF_LINES, path))
        else:
            os.makedirs(os.path.dirname(full), exist_ok=True)
            with open(full, "w") as f:
                f.write(new)
            print("wrote %s" % path)
    for e in errors:
        print("error: " + e)
    count = sum(len(d.params) for d in docs)
    if args.check:
        if stale:
            print("error: %s out of date: run /usr/bin/python3 scripts/parameters.py"
                  % ", ".join(stale))
        if stale or errors:
            return 1
        print("parameters: %d parameters of %d classes agree with the code (%d warnings)"
              % (count, len(docs), len(warnings)))
        return 0
    print("parameters: %d parameters of %d classes, %d warnings, %d errors"
          % (count, len(docs), len(warnings), len(errors)))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
