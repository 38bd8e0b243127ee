"""The comments against the code: each setting's default, unit and range as the code has them
(clamp macros, enumerations, probing the setters with out-of-range values), and the ranges and
defaults its comment states, which must agree."""
import re

from .config import INT_PROBE, PROBE, UNIT_PATTERNS, VECTOR_UNIT_PATTERNS
from .values import (enum_symbol, fmt_num, fmt_tuple, same, stated_defaults, stated_ranges,
                     stated_unit)


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
    probe = INT_PROBE if p.type in ("int", "long", "vtkIdType") else PROBE
    for v in (-probe, probe):
        o = cls()
        getattr(o, "Set" + p.name)(*([v] * p.size))
        out.append(tuple(getattr(o, "Get" + p.name)()))
    lows, highs = out
    if any(abs(x) >= probe for x in lows + highs):
        return None
    if len(set(lows)) == 1 and len(set(highs)) == 1:
        return (lows[0], highs[0])
    return None


def probe_list_size(cls, p):
    o = cls()
    count = getattr(o, "GetNumberOf%ss" % p.name)
    for _ in range(1000):
        getattr(o, p.setter)(*([0.5] * p.size))
    n = count()
    return n if n < 1000 else None


def check_param(klass, instance, p, params, loc, errors, warnings):
    """Default text, unit, range; the comment's own range and default against the code."""
    text = p.doc
    p.default_text = default_text(p)
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
        clamped_range(instance, p, ranges, stated, loc, errors, warnings)
    elif p.kind in ("enum", "bitmask"):
        enum_range(instance, p)
    elif p.kind == "bool":
        p.range_text = "on/off"
    elif p.kind == "string":
        p.range_text = "text"
    elif p.kind == "object":
        p.range_text = "`%s` or none" % p.object_type
    elif p.kind == "scalar":  # a hand-written setter
        probed_scalar_range(klass, p, stated, loc, errors, warnings)
    elif p.kind == "list":
        list_range(klass, p, stated, loc, errors)
    elif p.kind == "vector":
        vector_range(klass, p, stated, loc, errors, warnings)
    check_default(p, group, loc, errors, warnings)


def default_text(p):
    """The default of a new instance as the tables show it."""
    if p.kind == "enum":
        return "`%s`" % enum_symbol(p, p.default)
    if p.kind == "bitmask":
        bits = [n for n, v, _ in p.enum[1] if v and (p.default & v) == v]
        return " \\| ".join("`%s`" % b for b in bits) if bits else "0 (none)"
    if p.kind == "bool":
        return "on" if p.default else "off"
    if p.kind == "string":
        return "none" if p.default is None else '`"%s"`' % p.default
    if p.kind == "object":
        return "none" if p.default is None else "`%s`" % p.default.GetClassName()
    if p.kind == "vector":
        return fmt_tuple(p.default)
    if p.kind == "list":
        return "empty" if not p.default else "%d entries" % p.default
    return fmt_num(p.default)


def clamped_range(instance, p, ranges, stated, loc, errors, warnings):
    """A vtkSetClampMacro setting: Get<Name>MinValue()/MaxValue() against the stated range."""
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


def enum_range(instance, p):
    """An enumeration's values (those within its clamp, if any), or a bit mask's bits."""
    lo = getattr(instance, "Get%sMinValue" % p.name, lambda: None)()
    hi = getattr(instance, "Get%sMaxValue" % p.name, lambda: None)()
    entries = [e for e in p.enum[1] if p.kind == "bitmask" or lo is None or lo <= e[1] <= hi]
    p.range_text = ", ".join("`%s`=%d" % (n, v) for n, v, _ in entries)
    if p.kind == "bitmask":
        p.range_text = "any OR of " + p.range_text
        if hi is not None:
            p.range_text += " ([%s, %s])" % (fmt_num(lo), fmt_num(hi))
    p.enum_entries = entries


def probed_scalar_range(klass, p, stated, loc, errors, warnings):
    """A hand-written scalar setter: its snapped values or clamp, found by probing."""
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


def list_range(klass, p, stated, loc, errors):
    """A list setting: each entry's stated range and the number of entries the class keeps."""
    text = p.doc
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


def vector_range(klass, p, stated, loc, errors, warnings):
    """A vector setting: the stated range of each component against the probed clamp."""
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


def check_default(p, group, loc, errors, warnings):
    """The comment's own default must agree with the code."""
    defaults = stated_defaults(p.doc)
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
