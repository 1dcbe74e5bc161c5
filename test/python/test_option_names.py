# Copyright (c) 2026 expmap contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The names of the methods and of the settings chosen from a list are written
once (include/expmap/Option_names.h). Here the command-line program's help,
the Python module and the manual's option list must agree on them, on their
defaults and on the methods: a name added, renamed or dropped in one place
only fails here."""

import os
import re
import subprocess

import pytest

import expmap

# Each setting: Python's keyword, its enum class and the command-line flag
# (None where the command line has none).
SETTINGS = [
    ("laplacian", expmap.LaplacianMode, "--laplacian"),
    ("vertex_area", expmap.VertexArea, "--vertex-area"),
    ("factor_precision", expmap.FactorPrecision, "--factor-precision"),
    ("regularization", expmap.PoissonRegularization, None),
    ("angle_estimator", expmap.AngleEstimator, "--angles"),
    ("fallback", expmap.HeatFallback, "--fallback"),
]

MANUAL = os.path.join(os.path.dirname(__file__), "..", "..", "doc", "manual.md")


@pytest.fixture(scope="module")
def cli_help():
    cli = os.environ.get("EXPMAP_CLI")
    if not cli:
        pytest.skip("EXPMAP_CLI is not set (ctest sets it)")
    return subprocess.run([cli, "compute", "--help"], check=True, capture_output=True,
                          text=True).stdout


def cli_values(help_text, flag):
    """The values the help lists under `flag`: name -> whether it is the default."""
    lines = help_text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("  " + flag + " "))
    values = {}
    for line in lines[start + 1:]:
        if line.startswith("  --") or not line.startswith(" "):
            break
        match = re.match(r"^ {25}([a-z0-9-]+)(?: \(or [a-z0-9-]+\))?: ", line)
        if match:
            values[match.group(1)] = False
            last = match.group(1)
        if "(default)" in line:
            values[last] = True
    return values


def python_default(keyword):
    """The default the constructor's docstring marks for `keyword`."""
    doc = expmap.HeatExponentialMap.__init__.__doc__
    start = re.search(r"^" + keyword + r": a ", doc, re.M)  # its lines, not the signature's
    assert start, "HeatExponentialMap's docstring does not describe %s" % keyword
    match = re.search(r"'(\w+)' \(default\)", doc[start.start():])
    return match.group(1)


def manual_bullet(keyword):
    """The manual's option bullet for `keyword` (section 4): its default and text."""
    text = open(MANUAL, encoding="utf-8").read()
    match = re.search(r"^\* \*\*`" + keyword + r"`\*\* = (.*?)(?=^\* |^$)", text, re.M | re.S)
    assert match, "doc/manual.md has no option bullet for %s" % keyword
    return match.group(1)


@pytest.mark.parametrize("keyword,enum,flag", SETTINGS)
def test_python_cli_and_manual_name_the_same_values(cli_help, keyword, enum, flag):
    members = list(enum.__members__)
    bullet = manual_bullet(keyword)
    default = python_default(keyword)
    assert default in members
    assert bullet.startswith("`%s`" % default), \
        "doc/manual.md gives %s a default other than %s" % (keyword, default)
    if flag is None:
        for name in members:
            assert "`%s`" % name in bullet or name == default, \
                "doc/manual.md does not name %s's value %s" % (keyword, name)
        return
    listed = cli_values(cli_help, flag)
    assert sorted(name.replace("-", "_") for name in listed) == sorted(members), \
        "%s lists %s, Python has %s" % (flag, sorted(listed), members)
    assert [name for name, is_default in listed.items() if is_default] == \
        [default.replace("_", "-")]
    flags = re.search(r"`" + flag + r" ([a-z0-9|-]+)`", bullet)
    assert flags, "doc/manual.md's %s bullet does not give %s's values" % (keyword, flag)
    assert sorted(flags.group(1).split("|")) == sorted(listed), \
        "doc/manual.md lists %s for %s, the program %s" % (flags.group(1), flag, sorted(listed))


@pytest.mark.parametrize("keyword,enum,flag", SETTINGS)
def test_either_spelling_is_accepted(elephant, keyword, enum, flag):
    _, V, F = elephant
    name = list(enum.__members__)[0]
    hyphenated = name.replace("_", "-")
    if keyword in ("angle_estimator", "fallback"):
        heat = expmap.HeatExponentialMap(V, F)
        a = heat.compute(0, vertices=30, **{keyword: name})
        b = heat.compute(0, vertices=30, **{keyword: hyphenated})
        assert (a.uv == b.uv).all()
    else:
        expmap.HeatExponentialMap(V, F, **{keyword: hyphenated})
    with pytest.raises(ValueError, match=name):
        if keyword in ("angle_estimator", "fallback"):
            expmap.HeatExponentialMap(V, F).compute(0, vertices=30, **{keyword: "no such"})
        else:
            expmap.HeatExponentialMap(V, F, **{keyword: "no such"})


def test_methods_are_the_same_everywhere(cli_help):
    lines = cli_help.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("  --method M"))
    listed = []
    for line in lines[start + 1:]:
        match = re.match(r"^ {25}([a-z]+) ", line)
        if not match:
            break
        listed.append(match.group(1))
    assert listed == list(expmap.METHODS)
    for name, cls in expmap.METHODS.items():
        assert cls.__name__ in dir(expmap)


# Each numeric setting: Python's keyword, whether it is a query's setting,
# the command-line flag (None where the command line has none) and a value
# out of its range.
NUMERIC_SETTINGS = [
    ("time_factor", False, "--time-factor", 0.0),
    ("poisson_compression_tolerance", False, None, 1e-9),
    ("region_growth", True, None, 0.5),
    ("pruning_tolerance", True, None, -1.0),
    ("near_source_blend", True, "--near-source-blend", (3.0, 1.0)),
    ("query_threads", True, "--query-threads", 3),
]


def numbers(text):
    return [float(x) for x in re.findall(r"[0-9.]+(?:e-?[0-9]+)?", text)]


def python_range_and_default(keyword):
    """The range and default the constructor's docstring gives `keyword`."""
    doc = expmap.HeatExponentialMap.__init__.__doc__.split("\n", 1)[1]  # not the signature
    doc = " ".join(doc.split())
    match = re.search(r"(?:^| )" + keyword + r": .*? \(([^;()]+); default: (.+?)\)\.", doc)
    assert match, "HeatExponentialMap's docstring gives %s no range and default" % keyword
    return match.group(1), numbers(match.group(2))


@pytest.mark.parametrize("keyword,is_query,flag,bad", NUMERIC_SETTINGS)
def test_numeric_settings_agree_everywhere(cli_help, elephant, keyword, is_query, flag, bad):
    value_range, default = python_range_and_default(keyword)
    bullet = " ".join(manual_bullet(keyword).split())
    head = re.match(r"\{[^}]*\}|[^ ,:]+", bullet).group(0)  # "10", "{2, 6}"
    assert numbers(head) == default, \
        "doc/manual.md gives %s a default other than %s" % (keyword, default)
    assert value_range.lower() in bullet.lower(), \
        "doc/manual.md does not give %s's range (%s)" % (keyword, value_range)
    if flag is not None:
        lines = cli_help.splitlines()
        start = next(i for i, line in enumerate(lines) if line.startswith("  " + flag + " "))
        end = next(i for i in range(start + 1, len(lines)) if not lines[i].startswith("    "))
        block = " ".join(" ".join(lines[start:end]).split())
        match = re.search(r" \(([^;()]+); default: ([^)]+)\)$", block)
        assert match, "%s has no range and default in the help" % flag
        assert match.group(1) == value_range
        assert numbers(match.group(2)) == default
    _, V, F = elephant
    with pytest.raises(ValueError, match=re.escape("%s must be %s" % (keyword, value_range))):
        if is_query:
            expmap.HeatExponentialMap(V, F).compute(0, vertices=30, **{keyword: bad})
        else:
            expmap.HeatExponentialMap(V, F, **{keyword: bad})
