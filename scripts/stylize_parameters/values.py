"""Values and the text of comments: formatting numbers, parsing the values, ranges, defaults
and units a comment states, comparing them with the code's."""
import math
import re

from .config import NAMED_VALUES, NUM


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


def enum_symbol(p, value):
    for name, v, _ in p.enum[1]:
        if v == value:
            return name
    return str(value)


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


def plain(text):
    """Doc text for a tooltip: no markdown, normalized whitespace."""
    text = text.replace("<br>", " ").replace("`", "").replace("\\|", "|")
    return re.sub(r"\s+", " ", text).strip()
