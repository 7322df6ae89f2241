"""Reading and writing the plain ASCII OpenFOAM fields the case tests use.

Only what the tests need: vector and scalar lists as written by OpenFOAM
(lagrangian fields, the internal field of a volume field, patch values),
uniform lists written as N{value}, and writing a volVectorField whose
internal and patch values are given by a function of the position.
"""
import re

_NUMBER = r"[-+0-9.eE]+"
_VECTOR = re.compile(r"\((%s) (%s) (%s)\)" % (_NUMBER, _NUMBER, _NUMBER))


def _list_after(text, start):
    """The list that begins at or after offset start: (count, body)."""
    match = re.compile(r"(\d+)\s*([({])").search(text, start)
    count, bracket = int(match.group(1)), match.group(2)
    close = ")" if bracket == "(" else "}"
    depth, i = 0, match.end() - 1
    for j in range(i, len(text)):
        if text[j] == bracket:
            depth += 1
        elif text[j] == close:
            depth -= 1
            if depth == 0:
                return count, bracket, text[i + 1:j]
    raise ValueError("unterminated list")


def read_vectors(path, start_key=None):
    """Vectors of a lagrangian field file, or of the list after start_key."""
    text = open(path).read()
    body_start = text.index("}") + 1          # past the FoamFile header
    if start_key:
        body_start = text.index(start_key, body_start)
    count, bracket, body = _list_after(text, body_start)
    vectors = [tuple(float(g) for g in m.groups()) for m in _VECTOR.finditer(body)]
    if bracket == "{":                        # uniform list N{(x y z)}
        vectors = vectors * count
    if len(vectors) != count:
        raise ValueError("%s: %d vectors, header says %d" % (path, len(vectors), count))
    return vectors


def read_scalars(path):
    """Scalars of a lagrangian scalar field file."""
    text = open(path).read()
    count, bracket, body = _list_after(text, text.index("}") + 1)
    values = [float(v) for v in body.split()]
    if bracket == "{":
        values = values * count
    if len(values) != count:
        raise ValueError("%s: %d values, header says %d" % (path, len(values), count))
    return values


def write_vector_field(path, centres, patch_faces, function, dimensions="[0 1 -1 0 0 0 0]"):
    """Write volVectorField path with value function(x, y, z) at the cell
    centres and at the face centres of each patch (type calculated)."""
    def vector_list(points):
        rows = "\n".join("(%.17g %.17g %.17g)" % function(*p) for p in points)
        return "nonuniform List<vector>\n%d\n(\n%s\n)" % (len(points), rows)

    out = ["FoamFile\n{\n    version 2.0;\n    format ascii;\n"
           "    class volVectorField;\n    object U;\n}\n",
           "dimensions %s;\n" % dimensions,
           "internalField %s;\n" % vector_list(centres),
           "boundaryField\n{\n"]
    for name, faces in patch_faces.items():
        out.append("    %s\n    {\n        type calculated;\n        value %s;\n    }\n"
                   % (name, vector_list(faces)))
    out.append("}\n")
    open(path, "w").write("".join(out))
