"""Reading, writing and editing the plain ASCII OpenFOAM files the scripts use.

Reading: the vector and scalar lists OpenFOAM writes (a lagrangian field,
the internal field or a patch's value of a volume field), as N(...) or as
the uniform N{value}; a top-level number entry of a dictionary. Writing: a FoamFile header, a whole file, a
volVectorField whose values a function of the position gives. Editing: a
top-level entry of a dictionary, any entry through foamDictionary (set,
remove), a regular-expression edit, a block replaced by another.

SPDX-License-Identifier: GPL-3.0-or-later
"""
import os
import re
import subprocess

_NUMBER = r"[-+0-9.eE]+"
_VECTOR = re.compile(r"\((%s)\s+(%s)\s+(%s)\)" % (_NUMBER, _NUMBER, _NUMBER))
_LIST_START = re.compile(r"(\d+)\s*([({])")
_CLOSING = {"(": ")", "{": "}"}


# ------------------------------------------------------------------ reading

def matching(text, start):
    """The offset of the bracket that closes the one at text[start]."""
    bracket = text[start]
    close = _CLOSING[bracket]
    depth = 0
    for j in range(start, len(text)):
        if text[j] == bracket:
            depth += 1
        elif text[j] == close:
            depth -= 1
            if depth == 0:
                return j
    raise ValueError("unterminated '%s' at offset %d" % (bracket, start))


def _body(path):
    """The file's text past its FoamFile header, without // comments."""
    text = open(path).read()
    if "FoamFile" in text:
        text = text[text.index("}", text.index("FoamFile")) + 1:]
    return re.sub(r"//[^\n]*", "", text)


def _list(path, entry):
    """(count, bracket, body) of the list of entry: None for the first
    list in the file (a lagrangian field), 'internalField', or a patch
    name (its value in boundaryField)."""
    text = _body(path)
    start = 0
    try:
        if entry == "internalField":
            start = text.index("internalField")
        elif entry:
            start = text.index(entry, text.index("boundaryField"))
    except ValueError:
        raise ValueError("%s: no entry '%s'" % (path, entry)) from None
    match = _LIST_START.search(text, start)
    if match is None:
        raise ValueError("%s: no list after '%s'" % (path, entry or "the header"))
    bracket = match.end() - 1
    return int(match.group(1)), text[bracket], text[bracket + 1:matching(text, bracket)]


def read_vectors(path, entry=None):
    """The vectors of a field file as (x, y, z) tuples: a lagrangian field
    (entry None), the internal field ('internalField') or a patch's value
    (the patch's name). A uniform list N{(x y z)} gives N copies."""
    count, bracket, body = _list(path, entry)
    vectors = [tuple(float(g) for g in m.groups()) for m in _VECTOR.finditer(body)]
    if bracket == "{":
        vectors = vectors * count
    if len(vectors) != count:
        raise ValueError("%s: %d vectors, the list says %d" % (path, len(vectors), count))
    return vectors


def read_scalars(path, entry=None):
    """The scalars of a field file (entry as for read_vectors)."""
    count, bracket, body = _list(path, entry)
    values = [float(v) for v in body.split()]
    if bracket == "{":
        values = values * count
    if len(values) != count:
        raise ValueError("%s: %d values, the list says %d" % (path, len(values), count))
    return values


def read_lists(path, width=1):
    """The lists of a lagrangian field of fields (one list per particle,
    e.g. N ( n1 (a b ...) n2 (...) ... ), a list of size n uniform as
    n{a}): lists of floats (width 1: scalars, labels) or of tuples of width
    floats (vectors: width 3)."""
    tokens = re.findall(r"[(){}]|[^\s(){}]+", _body(path))
    k = 0

    def take():
        nonlocal k
        k += 1
        return tokens[k - 1]

    def item():
        if width == 1:
            return float(take())
        if take() != "(":
            raise ValueError("%s: a value of %d numbers expected" % (path, width))
        value = tuple(float(take()) for _ in range(width))
        if take() != ")":
            raise ValueError("%s: a value of %d numbers expected" % (path, width))
        return value

    count = int(take())
    if take() != "(":
        raise ValueError("%s: not a list of lists" % path)
    lists = []
    for _ in range(count):
        n = int(take())
        bracket = take()
        if bracket == "{":
            lists.append([item()] * n)
            take()
            continue
        values = []
        while tokens[k] != ")":
            values.append(item())
        take()
        if len(values) != n:
            raise ValueError("%s: a list of %d values says %d" % (path, len(values), n))
        lists.append(values)
    return lists


def read_entry(path, name):
    """The number of a top-level entry 'name value;' or 'name [dims] value;'
    of a dictionary file, or None when the entry is absent."""
    match = re.search(r"^\s*%s\s+(?:\[[^\]]*\]\s*)?(%s)\s*;" % (re.escape(name), _NUMBER),
                      _body(path), re.M)
    return float(match.group(1)) if match else None


# ------------------------------------------------------------------ writing

def header(cls, obj, note=None):
    """A FoamFile header of class cls and object obj, with a // note after it."""
    text = ("FoamFile\n{\n    version     2.0;\n    format      ascii;\n"
            "    class       %s;\n    object      %s;\n}\n" % (cls, obj))
    if note:
        text += "// %s\n" % note
    return text


def write_file(path, text):
    """Write text to path, making its folder."""
    folder = os.path.dirname(path)
    if folder:
        os.makedirs(folder, exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def write_dictionary(path, body, cls="dictionary", note=None):
    """Write an OpenFOAM file: a header (object: the file's name) and body."""
    write_file(path, header(cls, os.path.basename(path), note) + body)


def write_vector_field(path, centres, patches, function, dimensions="[0 1 -1 0 0 0 0]",
                       precision=17, note=None):
    """Write the volVectorField path with the value function(x, y, z) at the
    cell centres. patches: {name: face centres (a calculated patch with the
    function's values there) or the text of the patch's entries}."""
    vector = "(%%.%dg %%.%dg %%.%dg)" % (precision, precision, precision)

    def values(points):
        rows = "\n".join(vector % tuple(function(*p)) for p in points)
        return "nonuniform List<vector>\n%d\n(\n%s\n)" % (len(points), rows)

    out = ["dimensions %s;\n" % dimensions,
           "internalField %s;\n" % values(centres),
           "boundaryField\n{\n"]
    for name, patch in patches.items():
        entries = patch if isinstance(patch, str) else \
            "type calculated;\n        value %s;" % values(patch)
        out.append("    %s\n    {\n        %s\n    }\n" % (name, entries))
    out.append("}\n")
    write_dictionary(path, "".join(out), "volVectorField", note)


# ------------------------------------------------------------------ editing

def edit(path, pattern, replacement):
    """Replace pattern (a regular expression, ^ and $ at each line) in the
    file; ValueError if it is not there."""
    text, n = re.subn(pattern, replacement, open(path).read(), flags=re.M)
    if n == 0:
        raise ValueError("no '%s' in %s" % (pattern, path))
    with open(path, "w") as f:
        f.write(text)


def set_entry(path, name, value):
    """Set the top-level entry 'name value;' of a dictionary (it must be there)."""
    edit(path, r"^%s\s.*;" % re.escape(name), "%-15s %s;" % (name, value))


def set_nested(path, entry, value):
    """Set any entry of a dictionary, a/b/c for nested ones, to the text
    value (OpenFOAM's foamDictionary -set: added when it is not there)."""
    subprocess.run(["foamDictionary", "-set", value, "-entry", entry, path],
                   check=True, stdout=subprocess.DEVNULL)


def remove_entry(path, entry):
    """Remove an entry of a dictionary, a/b/c for nested ones (OpenFOAM's
    foamDictionary -remove)."""
    subprocess.run(["foamDictionary", "-remove", "-entry", entry, path],
                   check=True, stdout=subprocess.DEVNULL)


def replace_block(path, name, body):
    """Replace the contents of the block 'name { ... }' by body."""
    text = open(path).read()
    found = re.search(r"^([ \t]*)%s\s*\{" % re.escape(name), text, flags=re.M)
    if found is None:
        raise ValueError("no block '%s' in %s" % (name, path))
    indent = found.group(1)
    end = matching(text, found.end() - 1)
    text = (text[:found.start()] + "%s%s\n%s{\n%s%s}" % (indent, name, indent, body, indent)
            + text[end + 1:])
    with open(path, "w") as f:
        f.write(text)
