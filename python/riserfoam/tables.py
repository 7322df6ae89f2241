"""The library's text tables, read by column name.

The format (written by the C++ code: riserParticleTable's and
riserParticle's particles.dat, the contacts.dat of riserContact and of
riserParticle, riserParticle's sweep.dat and budget.dat, riserCarrierError's
errors.dat, the validation programs' tables): plain text, one row a line,
fields separated by white space; comment lines start with '#'. The last
comment line before the data names the columns, separated by white space
after the '#'. In that line a remark in parentheses, e.g.
'side(+1: x > x_c)' or '(dry normal impact, 10 mm)', is not a name (the
column is 'side'), and a caption ending in ':' before the names, e.g.
'riserParticle contacts:', is not one either.

A column holds floats when all its fields are numbers, strings otherwise.
A name with a unit in brackets, e.g. 'h[s]', is also found without it
('h') when that is unambiguous.

    table = read("postProcessing/riserParticle/particles.dat")
    table.names                  # the columns, in the file's order
    table["lift"]                # a column (numpy array)
    table.particle(0)            # the rows of origId 0 (a Table)
    table.group_by("origId")     # {origId: Table}
    table[1:], table[mask]       # rows
    table[0], for row in table   # a row as a dict {name: value}: row["t"]

SPDX-License-Identifier: GPL-3.0-or-later
"""
import re

import numpy as np


class UnknownColumn(KeyError):
    """A column name the table does not have."""

    def __str__(self):
        return self.args[0]


def header_names(line):
    """The column names of a header line ('# t x y ...')."""
    text = line.lstrip("#")
    while True:                          # remarks in parentheses, innermost first
        text, n = re.subn(r"\([^()]*\)", " ", text)
        if n == 0:
            break
    names = text.split()
    captions = [i for i, name in enumerate(names) if name.endswith(":")]
    if captions:
        names = names[captions[-1] + 1:]
    return names


def _resolve(names, name, path):
    """name, or the one name that is name with a unit ('h' for 'h[s]')"""
    if name in names:
        return name
    bare = [n for n in names if n.split("[")[0] == name]
    if len(bare) == 1:
        return bare[0]
    raise UnknownColumn("%s: no column '%s'; the columns are: %s"
                        % (path or "table", name, " ".join(names)))


class Row(dict):
    """One row of a table, {name: value}; names are found as in Table."""

    path = None

    def __missing__(self, name):
        return dict.__getitem__(self, _resolve(list(self), name, self.path))


def _row(names, values, path):
    row = Row(zip(names, values))
    row.path = path
    return row


def _column(fields):
    try:
        return np.array([float(v) for v in fields])
    except ValueError:
        return np.array(fields, dtype=str)


class Table:
    """Columns of equal length, by name; see the module's doc."""

    def __init__(self, names, columns, path=None):
        self.names = list(names)
        self.columns = dict(zip(self.names, columns))
        self.path = path

    # --- columns
    def _name(self, name):
        return _resolve(self.names, name, self.path)

    def column(self, name):
        """The column name (numpy array); UnknownColumn names the valid ones."""
        return self.columns[self._name(name)]

    def __contains__(self, name):
        try:
            self._name(name)
            return True
        except UnknownColumn:
            return False

    def keys(self):
        return list(self.names)

    def items(self):
        return [(n, self.columns[n]) for n in self.names]

    def matrix(self, *names):
        """The columns names side by side: a rows x len(names) float array."""
        return np.column_stack([self.column(n) for n in names]) if len(self) else \
            np.zeros((0, len(names)))

    # --- rows
    def __len__(self):
        return len(self.columns[self.names[0]]) if self.names else 0

    def take(self, rows):
        """The table of some rows: a slice, a boolean mask or indices."""
        return Table(self.names, [self.columns[n][rows] for n in self.names], self.path)

    def where(self, **equal):
        """The rows whose columns equal the values given, e.g. where(origId=0)."""
        mask = np.ones(len(self), dtype=bool)
        for name, value in equal.items():
            mask &= self.column(name) == value
        return self.take(mask)

    def particle(self, origId, origProc=None):
        """The rows of one particle (origId, and origProc if given)."""
        if origProc is None:
            return self.where(origId=origId)
        return self.where(origId=origId, origProc=origProc)

    def group_by(self, *names):
        """{value (a tuple for several names): the rows with it}, sorted;
        whole numbers as int."""
        def plain(v):
            v = v.item() if hasattr(v, "item") else v
            return int(v) if isinstance(v, float) and v.is_integer() else v
        keys = list(zip(*(self.column(n) for n in names)))
        out = {}
        for key in sorted(set(keys)):
            mask = np.array([k == key for k in keys], dtype=bool)
            out[tuple(plain(v) for v in key) if len(names) > 1 else plain(key[0])] = self.take(mask)
        return out

    def record(self, i):
        """Row i as a Row {name: value}."""
        return _row(self.names, [self.columns[n][i].item() for n in self.names], self.path)

    def __iter__(self):
        """The rows, each a Row {name: value}."""
        lists = [self.columns[n].tolist() for n in self.names]
        for values in zip(*lists):
            yield _row(self.names, values, self.path)

    def __getitem__(self, key):
        """table['name']: a column; table[i]: row i as a dict; a slice or a
        mask: a Table of those rows."""
        if isinstance(key, str):
            return self.column(key)
        if isinstance(key, (int, np.integer)):
            return self.record(key)
        return self.take(key)

    def __repr__(self):
        return "Table(%s: %d rows of %s)" % (self.path, len(self), " ".join(self.names))


def read(path):
    """The table in the file path (see the module's doc for the format)."""
    names, rows, number = None, [], 0
    with open(path) as f:
        for number, line in enumerate(f, 1):
            if line.startswith("#"):
                if not rows:
                    names = header_names(line)
                continue
            fields = line.split()
            if not fields:
                continue
            if names is None:
                raise ValueError("%s: data before a header line of column names" % path)
            if len(fields) != len(names):
                raise ValueError("%s:%d: %d fields, the header names %d columns (%s)"
                                 % (path, number, len(fields), len(names), " ".join(names)))
            rows.append(fields)
    if names is None:
        raise ValueError("%s: no header line of column names" % path)
    columns = [_column(list(c)) for c in zip(*rows)] if rows else \
        [np.zeros(0) for _ in names]
    return Table(names, columns, path)

