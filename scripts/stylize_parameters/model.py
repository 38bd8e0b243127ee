"""The classes, read through VTK's Python wrapping (the build's vtkstylize package): their
settings as Param, each class as a ClassDoc (introspection of the setters and getters, the
enumerations, the per-actor helpers, the passes a class owns)."""
import os
import re
import sys

from .checks import check_param
from .config import CLASSES, FILTER_CLASSES, PROBE, RENDERING_PLUMBING
from .values import enum_symbol, first_sentence, fmt_num, fmt_tuple, same, split_args


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
