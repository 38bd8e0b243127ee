"""The ParaView plugin's server-manager XML: Plugin/View/StylizePasses.xml (a proxy per pass),
Plugin/View/StylizeFilters.xml (the Filters module's filters and sources), and the generated
blocks of Plugin/View/StylizeView.xml (the view's exposed properties, the Stylized Surface
representation's per-actor lighting properties, the volume displays' StylizeVolume)."""
import math
import re
import textwrap
from xml.sax.saxutils import escape

from .config import (XML_ADVANCED_NAME, XML_ADVANCED_RULE, XML_ADVANCED_TEXT, XML_FILTER_PROXIES,
                     XML_GROUP, XML_INT_TYPES, XML_MODEL_SOURCES, XML_PROXIES, XML_SKIP,
                     XML_SLIDER_RATIO, XML_SOURCE_PROXIES, XML_SOURCES, XML_VIEW,
                     XML_VOLUME_DISPLAY_TEXT, XML_VOLUME_DISPLAYS, XML_WIDTH, XML_ZERO_MEANS)
from .values import enum_symbol, fmt_num, plain


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


def xml_source(cls, text):
    """The paper a comment cites with "eq. N" or "the paper", named: the class's, or for the
    lighting pass the one of the model the comment starts with."""
    # ("paper" alone is often the drawing's paper)
    if not re.search(r"\b[Ee]q\.\s*\d|\b(?:of|in|by) the paper\b|"
                     r"\bthe paper(?:'s| finds| says| uses| writes)\b", text):
        return ""
    owner = cls
    for prefix, model_class in XML_MODEL_SOURCES.items():
        if text.startswith(prefix):
            owner = model_class
    return "Source: %s." % XML_SOURCES[owner] if owner in XML_SOURCES else ""


def xml_documentation(p, kind, cls=""):
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
        # (the comment often states the range, or ends with the same sentence: not said twice)
        if sentence.lower() in parts[0].lower():
            sentence = ""
        elif rng and re.search(r"\bRange \[", parts[0]):
            sentence = "" if re.search(r"\bdefault\b", parts[0], re.I) else \
                "Default %s." % default
        if unit.strip() and unit.strip().lower() in parts[0].lower():
            unit = ""
        parts.append(unit + sentence)
    parts.append(xml_source(cls, parts[0]))
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
    """The lines of one property element."""
    loc = "%s::%s" % (d.cls, p.name)
    kind = xml_kind(p)
    size = p.size if p.kind in ("vector", "writeonly") else 1
    element = {"bool": "IntVectorProperty", "enum": "IntVectorProperty",
               "int": "IntVectorProperty", "double": "DoubleVectorProperty",
               "string": "StringVectorProperty"}[kind]
    L = xml_open(element, xml_property_attrs(p, kind, size, loc, errors), "      ")
    L.extend(xml_domain(d, p, kind, size, loc, errors))
    L.append("        <Documentation>")
    L.append(wrap_xml_text(xml_text(xml_documentation(p, kind, d.cls)), "          "))
    L.append("        </Documentation>")
    if kind == "string" and p.name == "FileName":
        L.append("        <Hints>")
        L.append("          <FileChooser extensions=\"%s\" file_description=\"%s\"/>" % (
            " ".join(e.lstrip(".") for e in d.klass.GetSupportedExtensions().split()),
            "Data files read with VTK Stylize's checks"))
        L.append("        </Hints>")
    L.append("      </%s>" % element)
    return L


def xml_property_attrs(p, kind, size, loc, errors):
    """[(attribute, value)] of a property element: name, command, size, defaults, hints."""
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
    # a 0 that stands for a choice made for the user says so in the label
    cls = loc.split("::")[0]
    zero = XML_ZERO_MEANS.get((cls, p.name))
    if zero:
        words = re.sub(r"(?<=[a-z])(?=[A-Z])", " ", p.name)
        attrs.append(("label", "%s (0 = %s)" % (words, zero)))
    elif kind in ("int", "double") and size == 1 and p.default == 0 and \
            re.search(r"(?:^|[.;] )0(?: \(default\))?:|\b0 \(default\) ", p.doc):
        errors.append("%s: its comment explains what 0 means, its default: add it to "
                      "XML_ZERO_MEANS so that the panel's label says so" % loc)
    if xml_advanced(p):
        attrs.append(("panel_visibility", "advanced"))
    is_color = (kind == "double" and size == 3
                and (re.search(r"Colou?r$", p.name) or p.unit == "RGB"))
    if is_color:
        attrs.append(("panel_widget", "color_selector"))
    return attrs


def xml_domain(d, p, kind, size, loc, errors):
    """The lines of a property's domain: boolean, enumeration, range or file list (or none)."""
    L = []
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
            # a range over more than three decades gets a text field: the domain without its
            # maximum (ParaView draws a slider only between a minimum and a maximum)
            ratio = rng[1] / rng[0] if rng[0] > 0 else rng[1] - rng[0]
            top = "" if ratio > XML_SLIDER_RATIO else ' max="%s"' % hi
            L.append('        <%sRangeDomain name="range" min="%s"%s/>' % (
                "Int" if kind == "int" else "Double", lo, top))
    elif kind == "string" and p.name == "FileName":
        L.append('        <FileListDomain name="files"/>')
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


def xml_proxy_close(factory=(), extensions=""):
    """The menu hint, the reader factory's hints ([(file description, extensions or None for the
    rest of `extensions`)]) and the closing tag of a proxy of the VTK Stylize category."""
    L = ["      <Hints>", '        <ShowInMenu category="VTK Stylize"/>']
    every = [e.lstrip(".") for e in extensions.split()]
    given = [e.lstrip(".") for _, listed in factory if listed for e in listed.split()]
    for description, listed in factory:
        exts = [e.lstrip(".") for e in listed.split()] if listed else \
            [e for e in every if e not in given]
        L.extend(xml_open("ReaderFactory", [("extensions", " ".join(exts)),
                                            ("file_description", description)], "        ",
                            "/>"))
    return L + ["      </Hints>", "    </SourceProxy>"]


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
    for name, cls, label, text, informations, pv_class, factory in XML_SOURCE_PROXIES:
        d = docs_by_class[cls]
        L.extend(xml_proxy_open(name, pv_class, label, d, text))
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
        L.extend(xml_proxy_close(factory, d.klass.GetSupportedExtensions()))
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
            inverse = ' inverse="1"' if style.startswith("!") else ""
            L.append('    <Hints><PropertyWidgetDecorator type="GenericDecorator" '
                     'mode="visibility" property="Style" value="%s"%s /></Hints>'
                     % (style.lstrip("!"), inverse))
        L.append("  </PropertyGroup>")
        L.append("</ExposedProperties>")
        return m.group(1) + "".join(indent + line + "\n" for line in L) + m.group(4)

    out = XML_VIEW_BLOCK.sub(block, view_xml)
    for name in proxies:
        if name not in seen:
            errors.append("%s: no <!-- generated:exposed:%s begin/end --> markers" % (XML_VIEW, name))
    return out


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


XML_VOLUME_BLOCK = re.compile(
    r"([ \t]*<!-- generated:volume-displays begin -->\n)(.*?)"
    r"([ \t]*<!-- generated:volume-displays end -->)", re.S)


def render_xml_volume_displays(view_xml, errors):
    """StylizeVolume on each of ParaView's representations with a Volume type (one extension
    each, the same property), shown with the Volume representation only."""
    m = XML_VOLUME_BLOCK.search(view_xml)
    if not m:
        errors.append("%s: no <!-- generated:volume-displays begin/end --> markers" % XML_VIEW)
        return view_xml
    body = []
    for name in XML_VOLUME_DISPLAYS:
        body += ['    <Extension name="%s">' % name,
                 '      <IntVectorProperty name="StylizeVolume" number_of_elements="1" '
                 'default_values="1">',
                 '        <BooleanDomain name="bool" />',
                 '        <Documentation>']
        body += wrap_xml_text(xml_text(XML_VOLUME_DISPLAY_TEXT), " " * 10).split("\n")
        body += ['        </Documentation>',
                 '        <Hints>',
                 '          <PropertyWidgetDecorator type="GenericDecorator" mode="visibility"',
                 '              property="Representation" value="Volume" />',
                 '        </Hints>',
                 '      </IntVectorProperty>',
                 '    </Extension>']
    return view_xml[:m.start(2)] + "".join(line + "\n" for line in body) + view_xml[m.end(2):]
