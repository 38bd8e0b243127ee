#!/usr/bin/python3
"""Parameter reference of the VTK Stylize passes, generated from the wrapped classes.

    /usr/bin/python3 scripts/parameters.py           # writes docs/PARAMETERS.md, the tables
                                                     # between markers in README.md and docs/,
                                                     # and the ParaView XML in Plugin/View/
    /usr/bin/python3 scripts/parameters.py --check   # verifies them, prints a diff, exit 1 on drift

The one source is the classes, read through VTK's Python wrapping (the build's vtkstylize
package); no header is parsed:

- the parameters: every Set<Name>/Get<Name> pair of the class and its bases below VTK's
  render-pass plumbing, in declaration order (the wrapping keeps the header's order);
- their meaning: the setter's docstring, which VTK's wrapping makes from the header comment (in a
  ///@{ group only the first method gets it: the others share it);
- defaults: Get<Name>() of a new instance;
- ranges: Get<Name>MinValue()/Get<Name>MaxValue() (vtkSetClampMacro); for other setters, found by
  setting out-of-range values and reading them back, else the range the comment states;
- enumerations: the class's enum named after the setting in the plural (Anchor -> Anchors, the
  project's convention; Channels -> ChannelBits is a bit mask), its constants the values;
- the per-actor settings: the static SetActor*() helpers, probed on an actor's property keys.

The comments' own statements of ranges and defaults are compared with the code: a contradiction is
an error, like a parameter without a comment. A missing unit, range or default in a comment is a
warning. Parameter tables in Markdown are generated copies between marker comments
(<!-- parameters:CLASS begin --> ... <!-- parameters:CLASS end -->) in README.md and docs/*.md;
--check also fails on a hand-written parameter table outside them.

The ParaView plugin's server-manager XML is generated from the same description:
Plugin/View/StylizePasses.xml (a proxy per pass, a property per parameter: kind, default, range
domain, documentation), the blocks of Plugin/View/StylizeView.xml between its
<!-- generated:exposed:PROXY begin/end --> markers (the view's <ExposedProperties>), and between
<!-- generated:representation begin/end --> the Stylized Surface representation's per-actor
lighting properties (those of vtkStylizeLightingPass that a SetActor*() helper overrides).
Object-valued parameters are not exposed, nor those in XML_SKIP (set by the view).

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

# The classes documented, in order.
CLASSES = ["vtkStylizeLightingPass", "vtkStylizeGBufferPass", "vtkComicPass", "vtkPixelArtPass",
           "vtkSketchPass", "vtkStylizePrincipalCurvatures", "vtkStylizeReader"]
# The classes of the Filters module (the others are passes).
FILTER_CLASSES = {"vtkStylizePrincipalCurvatures", "vtkStylizeReader"}

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
# Reading the classes through VTK's Python wrapping


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


def docstring_parts(method):
    """(signatures, text) of a wrapped method's docstring: the Python and C++ signatures, and the
    header comment (VTK's wrapping makes the comment above a declaration its docstring)."""
    doc = getattr(method, "__doc__", None) or ""
    blocks = doc.split("\n\n", 1)
    signatures = blocks[0]
    text = blocks[1] if len(blocks) > 1 else ""
    return signatures, re.sub(r"\s+", " ", text).strip()


def cxx_arguments(method):
    """[(type, name)] of the first C++ signature in a wrapped method's docstring."""
    signatures, _ = docstring_parts(method)
    m = re.search(r"C\+\+: [^(]*\(([^)]*)\)", signatures.replace("\n", " "))
    if not m or not m.group(1).strip():
        return []
    out = []
    for arg in split_args(m.group(1)):
        arg = re.sub(r"\s+", " ", arg.split("=")[0]).strip()
        am = re.match(r"(.*?)\s*(\w+)(\[\d*\])?$", arg)
        out.append((am.group(1).replace("const ", "").strip() + (am.group(3) or ""), am.group(2)))
    return out


def cxx_return(method):
    signatures, _ = docstring_parts(method)
    m = re.search(r"C\+\+: (?:(?:virtual|static|const) )*([\w:<>]+(?:\s*\*)?)\s*\w+\(", signatures)
    return m.group(1).replace(" ", "") if m else None


def framework_settings():
    """Settings of VTK's render-pass, algorithm and object plumbing (ActiveDrawBuffers, Debug,
    InputConnection, ...)."""
    from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLRenderPass
    from vtkmodules.vtkCommonExecutionModel import vtkPolyDataAlgorithm
    return {m[3:] for k in (vtkOpenGLRenderPass, vtkPolyDataAlgorithm) for m in dir(k)
            if m.startswith("Set")} | RENDERING_PLUMBING


# Settings of the style base that whoever renders sets, not the user's look (their comments say
# who sets them).
RENDERING_PLUMBING = {"WindowScale"}


class ClassDoc:
    pass


class Param:
    def __init__(self, name):
        self.name = name
        self.kind = None  # scalar, bool, enum, bitmask, string, object, vector
        self.setter = "Set" + name
        self.setter_args = []  # [(C++ type, name)]
        self.type = None
        self.size = 1
        self.clamp = False  # Get<Name>MinValue/MaxValue exist (vtkSetClampMacro)
        self.doc = ""  # the setter's comment (or its group's)
        self.enum = None  # (enum type name, [(symbol, value, note)])
        self.enum_entries = []
        self.conveniences = []  # [(method, own comment)]
        self.object_type = None
        self.default = None
        self.default_text = ""
        self.range_text = ""
        self.unit = "—"
        self.meaning_full = ""
        self.meaning_short = ""
        self.shared_with = None
        self.per_actor = []
        self.range_numbers = None
        self.allowed_values = None
        self.inherited = None  # the VTK or project base class that declares it


def enum_symbol(p, value):
    for name, v, _ in p.enum[1]:
        if v == value:
            return name
    return str(value)


def class_settings(klass, skip):
    """[(name, owner class)] of the Set<Name>/Get<Name> pairs, in declaration order (the wrapping
    keeps the header's order), the class's own first, then those of its bases."""
    out, seen = [], set()
    for base in klass.__mro__:
        for attr in base.__dict__:
            name = attr[3:]
            if not attr.startswith("Set") or name in seen or name in skip or "To" in name and \
                    hasattr(klass, "Set" + name.split("To")[0]) and \
                    hasattr(klass, "Get" + name.split("To")[0]):
                continue
            if not hasattr(klass, "Get" + name):
                continue
            seen.add(name)
            out.append((name, base))
    return out


def enum_of(klass, name):
    """(type name, [(symbol, value, '')]) of the enumeration a setting takes: the class's enum
    named after the setting in the plural (Anchor -> Anchors), as every enum of the project is,
    or after its last word (NormalPrecision -> Precisions)."""
    last = re.sub(r"^.*(?=[A-Z][a-z]+$)", "", name)
    for type_name in (name + "s", name + "es", re.sub(r"s$", "", name) + "Bits", last + "s",
                      last + "es"):
        t = getattr(klass, type_name, None)
        if isinstance(t, type) and issubclass(t, int):
            entries = sorted(((s, int(getattr(klass, s)), "") for s in dir(klass)
                              if type(getattr(klass, s)) is t), key=lambda e: e[1])
            return type_name, entries
    return None


def probe_scalar(cls, p):
    """Range of a setter without a clamp macro: set extremes and read them back."""
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


def as_python_default(p, value):
    if p.kind == "bool":
        return bool(value)
    if isinstance(value, int) and not isinstance(value, bool) and p.kind == "enum":
        return int(value)
    return value


def read_param(klass, instance, name, owner, project):
    """A Param from the wrapped class alone: kind, type, default, clamp range, comment."""
    p = Param(name)
    setter = getattr(klass, p.setter)
    p.setter_args = cxx_arguments(setter)
    p.doc = docstring_parts(setter)[1] or docstring_parts(getattr(klass, "Get" + name))[1]
    if owner.__name__ not in project:
        p.inherited = owner.__name__
    value = getattr(instance, "Get" + name)()
    p.enum = enum_of(klass, name)
    types = [t for t, _ in p.setter_args]
    p.type = types[0] if types else None
    p.clamp = hasattr(klass, "Get%sMinValue" % name) and hasattr(klass, "Get%sMaxValue" % name)
    if p.enum and p.enum[0].endswith("Bits"):
        p.kind = "bitmask"
    elif p.enum:
        p.kind = "enum"
    elif p.type == "bool":
        p.kind = "bool"
    elif p.type in ("char*", "char *", "std::string"):
        p.kind = "string"
    elif p.type and p.type.endswith("*") and p.type.startswith("vtk"):
        p.kind = "object"
        p.object_type = p.type.rstrip("*").strip()
    elif isinstance(value, tuple) or len(types) > 1 or (p.type and "[" in p.type):
        p.kind = "vector"
        p.size = len(value) if isinstance(value, tuple) else len(types)
        p.type = p.type.split("[")[0] if p.type else None
    else:
        p.kind = "scalar"
    p.default = as_python_default(p, value)
    # SetXToY() conveniences of an enumeration, On()/Off() of a boolean
    for attr in owner.__dict__:
        if attr.startswith(p.setter + "To"):
            p.conveniences.append((attr, docstring_parts(getattr(klass, attr))[1]))
    return p


def list_params(klass, instance):
    """List-valued settings: Add<Name>(...) with RemoveAll<Name>s() and GetNumberOf<Name>s()."""
    out = []
    for attr in klass.__dict__:
        name = attr[3:]
        if not attr.startswith("Add") or not hasattr(klass, "RemoveAll%ss" % name) or \
                not hasattr(klass, "GetNumberOf%ss" % name):
            continue
        p = Param(name)
        p.kind, p.setter = "list", attr
        p.setter_args = cxx_arguments(getattr(klass, attr))
        p.size = len(p.setter_args)
        p.type = p.setter_args[0][0] if p.setter_args else None
        p.doc = docstring_parts(getattr(klass, attr))[1]
        p.default = getattr(instance, "GetNumberOf%ss" % name)()
        out.append(p)
    return out


def probe_list_size(cls, p):
    o = cls()
    count = getattr(o, "GetNumberOf%ss" % p.name)
    for _ in range(1000):
        getattr(o, p.setter)(*([0.5] * p.size))
    n = count()
    return n if n < 1000 else None


def per_actor_settings(klass, params, errors, warnings):
    """The static Set<Actor...>(prop, ...) helpers: which keys they write, and their ranges."""
    from vtkmodules.vtkRenderingCore import vtkActor
    keys = [k for k in klass.__dict__ if re.fullmatch(r"[A-Z][A-Z0-9_]+", k)
            and callable(getattr(klass, k)) and cxx_return(getattr(klass, k)) and
            "Information" in (cxx_return(getattr(klass, k)) or "")]
    setters = [m for m in klass.__dict__ if m.startswith("SetActor")]
    removers = [m for m in klass.__dict__ if m.startswith("RemoveActor")]
    by_name = {p.name: p for p in params}
    actor = []
    for method in setters:
        args = cxx_arguments(getattr(klass, method))
        results = {}
        for v in (-PROBE, PROBE):
            a = vtkActor()
            getattr(klass, method)(a, *([v] * (len(args) - 1)))
            info = a.GetPropertyKeys()
            for k in keys:
                key = getattr(klass, k)()
                if info is not None and info.Has(key):
                    results.setdefault(k, []).append(info.Get(key))
        rows = []
        for kname, (lo, hi) in results.items():
            prop = "".join(w.capitalize() for w in kname.lower().split("_"))
            target = by_name.get(prop)
            rng = "[%s, %s]" % (fmt_num(lo), fmt_num(hi))
            if target is not None and target.range_numbers and not (
                    same(target.range_numbers[0], lo) and same(target.range_numbers[1], hi)):
                errors.append("%s::%s clamps %s to %s, the pass's %s to %s" % (
                    klass.__name__, method, kname, rng, prop, target.range_text))
            if target is not None:
                target.per_actor.append("`%s()`" % kname)
            rows.append((kname, prop if target is not None else None, rng))
        comment = docstring_parts(getattr(klass, method))[1]
        if not rows:
            warnings.append("%s::%s sets none of the keys %s" % (klass.__name__, method,
                                                                ", ".join(keys)))
        signature = "%s(prop, %s)" % (method, ", ".join(n for _, n in args[1:]))
        actor.append((signature, rows, comment))
    return (actor, [("%s(prop)" % m, docstring_parts(getattr(klass, m))[1]) for m in removers],
            [(k, docstring_parts(getattr(klass, k))[1]) for k in keys])


def nested_passes(klass, project):
    """[(getter, class name, comment)] of the passes a class owns (Get<Name>Pass() returning a
    project class, with no setter)."""
    out = []
    for m in dir(klass):
        if not m.startswith("Get") or hasattr(klass, "Set" + m[3:]):
            continue
        ret = (cxx_return(getattr(klass, m)) or "").rstrip("*")
        if ret in project and not cxx_arguments(getattr(klass, m)):
            out.append((m, ret, docstring_parts(getattr(klass, m))[1]))
    return out


def describe_class(mod, cls, errors, warnings):
    klass = getattr(mod, cls)
    instance = klass()
    project = {c for c in CLASSES} | {"vtkStylizeStylePass"}
    settings = class_settings(klass, framework_settings())
    params = [read_param(klass, instance, name, owner, project) for name, owner in settings]
    params += list_params(klass, instance)
    doc = ClassDoc()
    doc.cls, doc.params, doc.klass = cls, params, klass
    doc.path = "%s/%s.h" % ("Filters" if cls in FILTER_CLASSES else "Passes", cls)
    brief = (klass.__doc__ or "").split("\n\n", 1)[0]
    doc.brief = re.sub(r"\s+", " ", brief.split(" - ", 1)[-1]).strip()
    where = "%s::" % cls
    previous = None
    for p in params:
        loc = "%s%s" % (where, p.name)
        text = p.doc
        if not text and previous is not None and previous.doc:
            # a ///@{ group: the wrapping gives the comment to the group's first method only
            p.shared_with = previous.shared_with or previous.name
            text = p.doc = previous.doc
        elif not text:
            errors.append("%s: no doc comment" % loc)
        previous = p
        p.meaning_full = text or "(no doc comment)"
        p.meaning_short = first_sentence(text) if text else "(no doc comment)"
        if p.inherited:
            p.meaning_full = "Inherited from `%s` (VTK): %s" % (p.inherited, p.meaning_full)
            p.meaning_short = "Inherited from `%s` (VTK): %s" % (p.inherited, p.meaning_short)
        check_param(klass, instance, p, params, loc, errors, warnings)
    doc.actor, doc.actor_removers, doc.keys = per_actor_settings(klass, params, errors, warnings)
    doc.nested = nested_passes(klass, project)
    return doc


def check_param(klass, instance, p, params, loc, errors, warnings):
    """Default text, unit, range; the comment's own range and default against the code."""
    text = p.doc
    if p.kind == "enum":
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
    elif p.kind == "vector":
        p.default_text = fmt_tuple(p.default)
    elif p.kind == "list":
        p.default_text = "empty" if not p.default else "%d entries" % p.default
    else:
        p.default_text = fmt_num(p.default)
    if p.kind in ("scalar", "vector", "list"):
        unit = stated_unit(text, UNIT_PATTERNS if p.kind == "scalar" else VECTOR_UNIT_PATTERNS)
        if unit:
            p.unit = unit
        else:
            warnings.append("%s: the comment states no unit" % loc)
    group = [q for q in params if q.doc == p.doc]
    ranges = stated_ranges(text)
    stated = None
    if len(ranges) == 1:
        stated = ranges[0]
    elif ranges and len(ranges) == len(group):
        stated = ranges[group.index(p)]
    if p.kind == "scalar" and p.clamp:
        lo = getattr(instance, "Get%sMinValue" % p.name)()
        hi = getattr(instance, "Get%sMaxValue" % p.name)()
        p.range_numbers = (lo, hi)
        p.range_text = "[%s, %s]" % (fmt_num(lo), fmt_num(hi))
        if stated and not (same(stated[0], lo) and same(stated[1], hi)):
            errors.append("%s: the comment states the range [%s, %s], the code clamps to [%s, %s]"
                          % (loc, fmt_num(stated[0]), fmt_num(stated[1]), fmt_num(lo),
                             fmt_num(hi)))
        if not ranges:
            warnings.append("%s: the comment states no range (code: %s)" % (loc, p.range_text))
    elif p.kind in ("enum", "bitmask"):
        lo = getattr(instance, "Get%sMinValue" % p.name, lambda: None)()
        hi = getattr(instance, "Get%sMaxValue" % p.name, lambda: None)()
        entries = [e for e in p.enum[1] if p.kind == "bitmask" or lo is None or lo <= e[1] <= hi]
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
    elif p.kind == "scalar":  # a hand-written setter
        probed, values = probe_scalar(klass, p)
        if values:
            p.range_text = ", ".join(fmt_num(v) for v in values) + " (others are snapped)"
            p.range_numbers = (values[0], values[-1])
            p.allowed_values = values
        elif probed and probed[0] is not None:
            p.range_numbers = probed
            p.range_text = "[%s, %s]" % (fmt_num(probed[0]), fmt_num(probed[1]))
            if stated and not (same(stated[0], probed[0]) and same(stated[1], probed[1])):
                errors.append("%s: the comment states the range [%s, %s], the setter clamps to "
                              "%s" % (loc, fmt_num(stated[0]), fmt_num(stated[1]), p.range_text))
        elif stated:
            p.range_text = "[%s, %s]" % (fmt_num(stated[0]), fmt_num(stated[1]))
            p.range_numbers = stated
        else:
            p.range_text = "—"
            warnings.append("%s: the comment states no range" % loc)
    elif p.kind == "list":
        p.range_text = "each [%s, %s]" % (fmt_num(stated[0]), fmt_num(stated[1])) if stated \
            else "—"
        p.range_numbers = stated
        most = probe_list_size(klass, p)
        m = re.search(r"\bat most (\d+)", text)
        if most is not None:
            p.range_text += ", at most %d entries" % most
            if m and int(m.group(1)) != most:
                errors.append("%s: the comment says at most %s, the code keeps %d"
                              % (loc, m.group(1), most))
    elif p.kind == "vector":
        probed = probe_vector(klass, p)
        if stated:
            p.range_text = "each [%s, %s]" % (fmt_num(stated[0]), fmt_num(stated[1]))
            p.range_numbers = stated
            if probed and not (same(stated[0], probed[0]) and same(stated[1], probed[1])):
                errors.append("%s: the comment states %s, the setter clamps each component to "
                              "[%s, %s]" % (loc, p.range_text, fmt_num(probed[0]),
                                            fmt_num(probed[1])))
        elif probed:
            p.range_text = "each [%s, %s]" % (fmt_num(probed[0]), fmt_num(probed[1]))
            p.range_numbers = probed
        else:
            p.range_text = "—"
            warnings.append("%s: the comment states no range" % loc)
    # the comment's own default must agree with the code
    defaults = stated_defaults(text)
    mine = None
    if len(group) > 1 and len(defaults) == len(group):
        mine = defaults[group.index(p)]
    elif len(defaults) == 1 or (defaults and len(group) == 1):
        mine = defaults[0]
    if not defaults:
        warnings.append("%s: the comment states no default (code: %s)" % (loc, p.default_text))
    elif mine is not None:
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


def nested_differences(doc, docs_by_class):
    """How the passes a class owns differ from standalone instances of their class."""
    out = []
    instance = doc.klass()
    for method, base, _ in doc.nested:
        child = getattr(instance, method)()
        ref = docs_by_class.get(base)
        if child is None or ref is None:
            continue
        diffs = []
        for p in ref.params:
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
# Output


def anchor(cls):
    return cls.lower()


def render_parameters(docs):
    docs_by_class = {d.cls: d for d in docs}
    L = []
    L.append("# Parameters")
    L.append("")
    L.append("<!-- Generated by scripts/parameters.py from the built classes (VTK's Python "
             "wrapping). Do not edit: run `/usr/bin/python3 scripts/parameters.py`. -->")
    L.append("")
    L.append("Every user-settable parameter of the passes and the filters, generated by `scripts/parameters.py` "
             "so that it cannot drift from the code; `ctest -R docs.parameters` fails when this "
             "file or the parameter tables in the README and docs/ are out of date, when a parameter has no "
             "doc comment, or when a comment states a range or default the code does not have.")
    L.append("")
    L.append("- **parameter**: the VTK property, set with `Set<Name>()` and read with "
             "`Get<Name>()` (booleans also `<Name>On()`/`<Name>Off()`).")
    L.append("- **meaning**: the setter's docstring (VTK's wrapping makes it from the header "
             "comment).")
    L.append("- **unit**: as the comment states it (— where it states none; points are pixels "
             "of an image `ReferenceHeight` pixels tall).")
    L.append("- **range**: for clamped settings `Get<Name>MinValue()`/`Get<Name>MaxValue()`; for "
             "enumerations the symbolic values (class constants, e.g. "
             "`vtkComicPass.OBJECT`); for other setters the range the comment states, checked "
             "by setting out-of-range values and reading them back (else as the comment states it). Setters clamp: out-of-range "
             "values take the nearest bound.")
    L.append("- **default**: `Get<Name>()` of a new instance.")
    L.append("")
    L.append("Classes: " + ", ".join("[`%s`](#%s)" % (d.cls, anchor(d.cls)) for d in docs) + ".")
    for d in docs:
        L.append("")
        L.append("## %s" % d.cls)
        L.append("")
        L.append("%s (`%s`)" % (d.brief, d.path))
        L.append("")
        L.append("| parameter | unit | range | default | meaning |")
        L.append("|---|---|---|---|---|")
        for p in d.params:
            name = "`%s()`" % p.setter if p.kind == "list" else "`%s`" % p.name
            if p.shared_with:
                meaning = "See `%s`." % p.shared_with
            else:
                meaning = p.meaning_full
            extra = []
            if p.enum and p.kind in ("enum", "bitmask"):
                extra.extend("`%s` (%d): %s" % (n, v, doc) if doc else "`%s` (%d)" % (n, v)
                             for n, v, doc in getattr(p, "enum_entries", p.enum[1]))
            for method, own in p.conveniences:
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


def render_readme_block(d, path):
    link = os.path.relpath(OUTPUT, os.path.dirname(path) or ".")
    L = []
    L.append("Generated by `scripts/parameters.py` from the class (full comments: "
             "[%s](%s#%s)):" % (OUTPUT, link, anchor(d.cls)))
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


def render_readme(path, text, docs, errors):
    by_class = {d.cls: d for d in docs}

    def replace(m):
        d = by_class.get(m.group(2))
        if d is None:
            errors.append("%s: parameters block for unknown class %s" % (path, m.group(2)))
            return m.group(0)
        return m.group(1) + render_readme_block(d, path) + "\n" + m.group(4)

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
                          "<!-- parameters:CLASS --> blocks" % (path, number, ", ".join(hits)))
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
XML_SKIP = {("vtkStylizeLightingPass", "Model"): "set by the view",
            ("vtkSketchPass", "SceneBounds"): "set by the view (the data's bounds on all ranks)",
            ("vtkSketchPass", "DirectionArrayName"):
                "ParaView's data is composite: Model reads its tangents, which the Principal "
                "Curvatures filter's TangentDirection picks"}
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
        # (the comment often ends with the same sentence: not said twice)
        if sentence.lower() in parts[0].lower():
            sentence = ""
        if unit.strip() and unit.strip().lower() in parts[0].lower():
            unit = ""
        parts.append(unit + sentence)
    return " ".join(t.strip() for t in parts if t.strip())


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
    loc = "%s::%s" % (d.cls, p.name)
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
    elif kind == "string" and p.name == "FileName":
        L.append('        <FileListDomain name="files"/>')
    L.append("        <Documentation>")
    L.append(wrap_xml_text(xml_text(xml_documentation(p, kind)), "          "))
    L.append("        </Documentation>")
    if kind == "string" and p.name == "FileName":
        L.append("        <Hints>")
        L.append("          <FileChooser extensions=\"%s\" file_description=\"%s\"/>" % (
            " ".join(e.lstrip(".") for e in d.klass.GetSupportedExtensions().split()),
            "Data files read with VTK Stylize's checks"))
        L.append("        </Hints>")
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
         "  Generated by scripts/parameters.py from the built classes (VTK's Python wrapping);",
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


XML_FILTERS = "Plugin/View/StylizeFilters.xml"
# (proxy name, class, label, input data type, help): ParaView filters of the Filters module.
XML_FILTER_PROXIES = [
    ("PrincipalCurvatures", "vtkStylizePrincipalCurvatures", "Principal Curvatures", "vtkPolyData",
     "Principal curvatures and directions of a surface (its polygons; run Extract Surface on "
     "other data first). The Stylize view's Sketch draws along them with Direction Source "
     "Model: the direction chosen by Tangent Direction becomes the point data's tangents."),
]
# (proxy name, class, label, help, information properties: (name, getter, documentation)):
# ParaView sources (readers) of the Filters module. Not
# registered for any extension (ParaView's own readers stay the ones File > Open picks): they
# are in the Sources menu and in Python (paraview.simple.StylizeCheckedReader).
XML_SOURCE_PROXIES = [
    ("StylizeCheckedReader", "vtkStylizeReader", "Stylize Checked Reader",
     "For files that may be broken or hostile: the same checks as the vtkstylize command, so "
     "that such a file gives one error line instead of crashing, hanging or exhausting the "
     "memory of the server.",
     [("ErrorMessage", "GetErrorMessage",
       "The reason the last read failed, one line (empty after a success); read it with "
       "UpdatePropertyInformation() and GetPropertyValue(\"ErrorMessage\").")]),
]


def xml_proxy_open(name, cls, label, d, text):
    """A proxy's opening tag and documentation (the class's brief, then text)."""
    return ['    <SourceProxy name="%s" class="%s" label="%s">' % (name, cls, xml_attr(label)),
            "      <Documentation>",
            wrap_xml_text(xml_text(plain(d.brief) + " " + text), "        "),
            "      </Documentation>"]


def xml_proxy_properties(d, errors):
    """One property per exposed parameter of the class."""
    L = []
    for p in d.params:
        if xml_kind(p) is not None:
            L.extend(xml_property(d, p, errors))
    return L


def xml_proxy_close():
    """The menu hint and the closing tag of a proxy of the VTK Stylize category."""
    return ["      <Hints>", '        <ShowInMenu category="VTK Stylize"/>', "      </Hints>",
            "    </SourceProxy>"]


def render_xml_filters(docs_by_class, errors):
    L = ["<!--",
         "  Generated by scripts/parameters.py from the built classes (VTK's Python wrapping);",
         "  do not edit by hand: run /usr/bin/python3 scripts/parameters.py (ctest -R",
         "  docs.parameters fails when this file is out of date).",
         "",
         "  One filter or source proxy per class of the Filters module, one property per user",
         "  parameter (docs/PARAMETERS.md).",
         "-->",
         "<ServerManagerConfiguration>",
         '  <ProxyGroup name="filters">']
    for name, cls, label, data_type, text in XML_FILTER_PROXIES:
        d = docs_by_class[cls]
        L.extend(xml_proxy_open(name, cls, label, d, text))
        L.append('      <InputProperty name="Input" command="SetInputConnection">')
        L.append('        <ProxyGroupDomain name="groups">')
        L.append('          <Group name="sources"/>')
        L.append('          <Group name="filters"/>')
        L.append("        </ProxyGroupDomain>")
        L.append('        <DataTypeDomain name="input_type">')
        L.append('          <DataType value="%s"/>' % data_type)
        L.append("        </DataTypeDomain>")
        L.append("        <Documentation>The surface (%s).</Documentation>" % data_type)
        L.append("      </InputProperty>")
        L.extend(xml_proxy_properties(d, errors))
        L.extend(xml_proxy_close())
    L.append("  </ProxyGroup>")
    L.append('  <ProxyGroup name="sources">')
    for name, cls, label, text, informations in XML_SOURCE_PROXIES:
        d = docs_by_class[cls]
        L.extend(xml_proxy_open(name, cls, label, d, text))
        L.extend(xml_proxy_properties(d, errors))
        for info, getter, doc in informations:
            if not hasattr(d.klass, getter):
                errors.append("%s: no method %s for the information property %s" % (
                    cls, getter, info))
            L.extend(xml_open("StringVectorProperty", [
                ("name", info), ("command", getter), ("information_only", "1"),
                ("number_of_elements", "1"), ("default_values", "")], "      "))
            L.append("        <Documentation>")
            L.append(wrap_xml_text(xml_text(doc), "          "))
            L.append("        </Documentation>")
            L.append("      </StringVectorProperty>")
        L.extend(xml_proxy_close())
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


# ------------------------------------------------------------------------------------------------
# The command line's option table (vtkstylize)

CLI_TABLE = "Examples/vtkstylize/vtkstylizeSettings.inc"
# How vtkstylize spells each setting it offers: (class, setting) -> (option, metavar, keyword
# spellings of an enumeration). The spelling is the command line's presentation (kept stable for
# scripts); what a setting is, its type, range, default, values and meaning come from the class.
CLI_COMIC = [
    ("EdgeWidth", "--edge-width", "PT"), ("DepthThreshold", "--depth-threshold", "T"),
    ("NormalThreshold", "--normal-threshold", "T"), ("ColorThreshold", "--color-threshold", "T"),
    ("DotSpacing", "--dot-spacing", "PT"), ("DotAngle", "--dot-angle", "DEG"),
    ("HatchSpacing", "--hatch-spacing", "PT"), ("HatchWidth", "--hatch-width", "PT"),
    ("HatchAngle", "--hatch-angle", "DEG"), ("BrightThreshold", "--bright", "T"),
    ("DarkThreshold", "--dark", "T"), ("CrossThreshold", "--cross-threshold", "T"),
    ("ReferenceHeight", "--reference-height", "PX"), ("HatchDirections", "--hatch-directions", "N"),
    ("EdgeWeights", "--edge-weights", "D,N,C"),
    ("Anchor", "--anchor", "screen|object", {"screen": "SCREEN", "object": "OBJECT"}),
    ("HatchOrientation", "--hatch-orientation", "fixed|principal",
     {"fixed": "FIXED", "principal": "PRINCIPAL"}),
    ("Edges", "--no-edges", None), ("Dots", "--no-dots", None), ("Hatching", "--no-hatching", None),
    ("CrossHatching", "--no-cross", None), ("Tinted", "--tinted", None),
]
CLI_PIXEL = [
    ("LowThreshold", "--low-threshold", "T"), ("HighThreshold", "--high-threshold", "T"),
    ("DitherStrength", "--dither-strength", "S"), ("PixelSize", "--pixel-size", "PX"),
    ("ArtPixelsAcross", "--art-pixels", "N"), ("HysteresisIterations", "--hysteresis", "N"),
    ("Levels", "--levels", "K"), ("DitherSize", "--dither-size", "N"),
    ("ColormapColors", "--colormap-colors", "N"), ("ColormapShades", "--colormap-shades", "N"),
    ("DepthThreshold", "--depth-threshold", "T"), ("NormalThreshold", "--normal-threshold", "T"),
    ("Mode", "--mode", "fast|faithful", {"fast": "FAST", "faithful": "FAITHFUL"}),
    ("EdgeDetector", "--edge-detector", "none|sobel|canny",
     {"none": "NO_EDGES", "sobel": "SOBEL", "canny": "CANNY"}),
    ("DitherAnchor", "--dither-anchor", "screen|grid|surface",
     {"screen": "SCREEN", "grid": "GRID", "surface": "SURFACE"}),
    ("Layer", "--pixel-layer", "art|pixelated|edges",
     {"art": "PIXEL_ART", "pixelated": "PIXELATED", "edges": "EDGES"}),
    ("OutlineColor", "--outline", "COLOR"),
    ("DepthEdges", "--no-depth-edges", None), ("NormalEdges", "--normal-edges", None),
    ("SnapToGrid", "--no-snap", None), ("StylizeBackground", "--stylize-background", None),
]
CLI_SKETCH = [
    ("Neighbors", "--neighbors", "2|4|8", {"2": "2", "4": "4", "8": "8"}),
    ("NeighborSpacing", "--neighbor-spacing", "PT"), ("MaxStride", "--max-stride", "PT"),
    ("ObjectScale", "--object-scale", "F"),
    ("PlanarTolerance", "--planar-tolerance", "T"),
    ("UmbilicTolerance", "--umbilic-tolerance", "T"), ("FillRadius", "--fill-radius", "PT"),
    ("FallbackAngle", "--fallback-angle", "DEG"), ("StepLength", "--step-length", "PT"),
    ("NoiseSize", "--noise-size", "PT"), ("StrokeContrast", "--stroke-contrast", "C"),
    ("Contrast", "--contrast", "C"), ("BlurRadius", "--blur-radius", "PT"),
    ("SmoothingRadius", "--smoothing-radius", "PT"),
    ("SmoothingIterations", "--smoothing", "N"), ("Steps", "--steps", "N"),
    ("BlurStride", "--blur-stride", "K"),
    ("DirectionSource", "--direction-source", "screen|model",
     {"screen": "SCREEN", "model": "MODEL"}),
    ("Direction", "--direction", "minimum|maximum|bisector",
     {"minimum": "MINIMUM", "maximum": "MAXIMUM", "bisector": "BISECTOR"}),
    ("Noise", "--noise", "white|perlin|worley|sparse",
     {"white": "WHITE", "perlin": "PERLIN", "worley": "WORLEY", "sparse": "SPARSE"}),
    ("NoiseSpace", "--noise-space", "object|screen", {"object": "OBJECT", "screen": "SCREEN_SPACE"}),
    ("LicMode", "--lic", "perspective|screen2d",
     {"perspective": "PERSPECTIVE", "screen2d": "SCREEN_2D"}),
    ("Layer", "--sketch-layer", "sketch|directions|strokes|tone",
     {"sketch": "SKETCH", "directions": "DIRECTIONS", "strokes": "STROKES", "tone": "TONE"}),
    ("BrightThresholds", "--bright-thresholds", "T1,T2"), ("CrossThreshold", "--cross-threshold", "T"),
    ("PencilColor", "--pencil", "COLOR"), ("PaperColor", "--paper", "COLOR"),
    ("CrossHatching", "--no-cross", None), ("Tinted", "--tinted", None),
]
CLI_LIGHTING = [
    ("SubjectFactor", "--subject", "P1"), ("GrayLevelsNear", "--levels-near", "N"),
    ("GrayLevelsFar", "--levels-far", "N"), ("SpecularGain", "--specular-gain", "G"),
    ("Scattering", "--scattering", "S"), ("SpecularOcclusion", "--occlusion", "M"),
]
CLI_OPTIONS = [("vtkComicPass", "comic", CLI_COMIC), ("vtkPixelArtPass", "pixel", CLI_PIXEL),
               ("vtkSketchPass", "sketch", CLI_SKETCH),
               ("vtkStylizeLightingPass", "lighting", CLI_LIGHTING)]
# Settings the command line offers by hand (vtkstylize's Options.cxx), and why.
CLI_BY_HAND = [
    "vtkStylizeLightingPass Model: --lighting takes the model's name (GetModelFromName)",
    "vtkPixelArtPass Palette: --palette also offers 1bit and 4grays (palette and levels at once)",
    "vtkPixelArtPass AddPaletteColor: --colors takes a list and selects the CUSTOM palette",
    "vtkSketchPass ReferenceHeight: --reference-height 0 means window pixels for the sketch "
    "(the pass itself needs at least 1)",
    "vtkSketchPass DirectionSource model: the program also computes the principal directions",
]


def c_string(text):
    return '"%s"' % text.replace("\\", "\\\\").replace('"', '\\"')


def render_cli_table(by_class, errors):
    L = ["// Generated by scripts/parameters.py from the wrapped classes. Do not edit: run",
         "// /usr/bin/python3 scripts/parameters.py (ctest -R docs.parameters fails when this file",
         "// is out of date). vtkstylize's option table: one line per pass setting it offers.",
         "//   STYLIZE_NUMBER(Class, Setting, Type, option, metavar, help): range and default are",
         "//     read from the class at run time (Get<Setting>MinValue/MaxValue, a new instance)",
         "//   STYLIZE_FLAG(Class, Setting, Value, option, help): sets Setting to Value",
         "//   STYLIZE_KEYWORDS(Class, Setting, option, metavar, help, {keyword, value}...)",
         "//   STYLIZE_VECTOR(Class, Setting, Type, Count, Min, Max, option, metavar, help)",
         "//   STYLIZE_COLOR(Class, Setting, option, metavar, help): R,G,B in [0, 1] or #rrggbb",
         "// Offered by hand instead:"]
    L.extend("//   %s" % why for why in CLI_BY_HAND)
    for cls, prefix, entries in CLI_OPTIONS:
        params = {p.name: p for p in by_class[cls].params}
        for entry in entries:
            setting, option, metavar = entry[:3]
            p = params.get(setting)
            if p is None:
                errors.append("%s: %s has no setting %s (offered as %s)" % (CLI_TABLE, cls,
                                                                           setting, option))
                continue
            meaning = plain(first_sentence(p.doc)).rstrip(".")
            if len(meaning) > 1 and meaning[1].islower():
                meaning = meaning[0].lower() + meaning[1:]
            help_text = c_string("%s: %s" % (prefix, meaning))
            if p.kind == "bool":
                value = "false" if option.startswith("--no-") else "true"
                L.append("STYLIZE_FLAG(%s, %s, %s, %s, %s)" % (cls, setting, value,
                                                               c_string(option), help_text))
            elif p.kind == "enum" or len(entry) > 3:
                words = entry[3]
                known = {n for n, _, _ in p.enum[1]} if p.enum else set()
                values = []
                for word, symbol in words.items():
                    if p.enum and symbol not in known:
                        errors.append("%s: %s has no value %s" % (CLI_TABLE, cls, symbol))
                    values.append("{ %s, %s }" % (c_string(word), "%s::%s" % (cls, symbol)
                                                  if p.enum else symbol))
                L.append("STYLIZE_KEYWORDS(%s, %s, %s, %s, %s, %s)" % (
                    cls, setting, c_string(option), c_string(metavar), help_text,
                    ", ".join(values)))
            elif p.kind == "vector" and metavar == "COLOR":
                L.append("STYLIZE_COLOR(%s, %s, %s, %s, %s)" % (cls, setting, c_string(option),
                                                                c_string(metavar), help_text))
            elif p.kind == "vector":
                lo, hi = p.range_numbers
                L.append("STYLIZE_VECTOR(%s, %s, double, %d, %s, %s, %s, %s, %s)" % (
                    cls, setting, p.size, repr(float(lo)), repr(float(hi)), c_string(option),
                    c_string(metavar), help_text))
            elif p.kind == "scalar" and p.clamp:
                ctype = "int" if p.type == "int" else "double"
                L.append("STYLIZE_NUMBER(%s, %s, %s, %s, %s, %s)" % (
                    cls, setting, ctype, c_string(option), c_string(metavar), help_text))
            else:
                errors.append("%s: %s::%s (%s) cannot be an option" % (CLI_TABLE, cls, setting,
                                                                     p.kind))
    L.append("")
    return "\n".join(L)


XML_REPRESENTATION_BLOCK = re.compile(
    r"([ \t]*<!-- generated:representation begin -->\n)(.*?)"
    r"([ \t]*<!-- generated:representation end -->)", re.S)


def render_xml_representation(view_xml, lighting, errors):
    """The Stylized Surface representation's per-actor lighting properties: the lighting pass's
    settings that a SetActor*() helper overrides, with the pass's default, range and comment
    (vtkStylizeSurfaceRepresentation forwards them to a vtkStylizeLightingPass)."""
    m = XML_REPRESENTATION_BLOCK.search(view_xml)
    if not m:
        errors.append("%s: no <!-- generated:representation begin/end --> markers" % XML_VIEW)
        return view_xml
    body = "".join(line + "\n" for p in lighting.params if p.per_actor
                   for line in xml_property(lighting, p, errors))
    return view_xml[:m.start(2)] + body + view_xml[m.end(2):]


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
    docs = [describe_class(mod, cls, errors, warnings) for cls in CLASSES]
    generated = render_parameters(docs)
    outputs = [(OUTPUT, generated)]
    blocks = 0
    for path in [README] + sorted(os.path.relpath(f, ROOT) for f in
                                  glob.glob(os.path.join(ROOT, "docs", "*.md"))):
        if path == OUTPUT:
            continue
        with open(os.path.join(ROOT, path)) as f:
            text = f.read()
        blocks += len(BLOCK.findall(text))
        outputs.append((path, render_readme(path, text, docs, errors)))
    if not blocks:
        warnings.append("no <!-- parameters:CLASS begin --> blocks in %s or docs/" % README)

    by_class = {d.cls: d for d in docs}
    exposed, skipped = xml_exposed(by_class, errors)
    xml_passes = render_xml_passes(by_class, exposed, skipped)
    with open(os.path.join(ROOT, XML_VIEW)) as f:
        xml_view = render_xml_view(f.read(), exposed, errors)
    xml_view = render_xml_representation(xml_view, by_class["vtkStylizeLightingPass"], errors)

    if not args.quiet:
        for w in warnings:
            print("warning: " + w)
    outputs += [(XML_PASSES, xml_passes), (XML_VIEW, xml_view),
                (XML_FILTERS, render_xml_filters(by_class, errors)),
                (CLI_TABLE, render_cli_table(by_class, errors))]
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
