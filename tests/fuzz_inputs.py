"""Hypothesis strategies for hostile inputs: URDF documents, DH arms, report JSON.

Each strategy starts from a valid input and mutates it at random, the way a careless
user or an attacker would: missing or wrong attributes, bad, huge, tiny or non-finite
numbers, duplicated names, cycles, unknown types, deep nesting, many elements, and
(for text) truncation, DTDs and entities, control characters and bytes that are not
UTF-8.

Strategies
----------
urdf_documents()
    ``(data, tip)``: the bytes of a URDF file (mostly UTF-8) and a tip link (or None).
dh_models()
    Model dicts with one or two arms given by DH tables, mutated.
mutated(base, leaves)
    ``base`` (a JSON-like tree) with a few entries replaced by ``leaves`` (or by other
    values), deleted or added.

Example
-------
>>> document([("link", {"name": "b"}, [])])
'<robot name="r"><link name="b"/></robot>'
"""

from __future__ import annotations

import copy
from typing import Any
from xml.sax.saxutils import quoteattr

from hypothesis import strategies as st

PAYLOAD_MARKER_NAME = "_fuzz_marker_must_not_exist"


def payloads(marker: str) -> list[str]:
    """Texts that would create the file ``marker`` if they were ever evaluated."""
    return [
        f"__import__('os').system('touch {marker}')",
        f"__import__('pathlib').Path('{marker}').touch()",
        f"open('{marker}', 'w')",
        f"(lambda: open('{marker}', 'w'))()",
        f"().__class__.__base__.__subclasses__()[0]('{marker}')",
        f"Integer(open('{marker}','w'))",
        f"L + exec(\"open('{marker}','w')\")",
    ]


# ------------------------------------------------------------------ trees in general


def tree_paths(tree: Any, prefix: tuple = ()):
    """Every path (tuple of keys and indices) in a JSON-like tree, the root first."""
    yield prefix
    if isinstance(tree, dict):
        for k, v in tree.items():
            yield from tree_paths(v, (*prefix, k))
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            yield from tree_paths(v, (*prefix, i))


def _depth(tree: Any, limit: int = 8) -> int:
    """Nesting of lists and mappings in ``tree``, counted up to ``limit``."""
    if limit == 0 or not isinstance(tree, dict | list):
        return 0
    items = tree.values() if isinstance(tree, dict) else tree
    return 1 + max((_depth(v, limit - 1) for v in items), default=0)


def nested(depth: int, leaf: Any = 0) -> Any:
    """``leaf`` inside ``depth`` alternating lists and mappings."""
    out = leaf
    for k in range(depth):
        out = [out] if k % 2 else {"k": out}
    return out


@st.composite
def mutated(draw, base: Any, leaves: st.SearchStrategy, max_changes: int = 4):
    """``base`` with 1..max_changes entries replaced (by a leaf, or by another entry of
    the tree), deleted or added."""
    tree = copy.deepcopy(base)
    for _ in range(draw(st.integers(1, max_changes))):
        paths = [p for p in tree_paths(tree) if p]
        if not paths:
            break
        path = draw(st.sampled_from(paths))
        parent = tree
        for key in path[:-1]:
            parent = parent[key]
        action = draw(st.sampled_from(["replace", "replace", "delete", "add", "copy"]))
        # leaves are copied: a list or mapping among them is shared by every draw
        if action == "replace":
            parent[path[-1]] = copy.deepcopy(draw(leaves))
        elif action == "copy":  # another entry of the tree (a duplicate, a wrong type)
            other = draw(st.sampled_from(paths))
            value: Any = tree
            for key in other:
                value = value[key]
            if _depth(value) <= 3:  # copies of copies of the root would grow forever
                parent[path[-1]] = copy.deepcopy(value)
        elif action == "delete" and isinstance(parent, dict):
            del parent[path[-1]]
        elif action == "delete":
            parent.pop(path[-1])
        elif isinstance(parent, dict):
            parent[draw(st.text(max_size=8))] = copy.deepcopy(draw(leaves))
        else:
            parent.append(copy.deepcopy(draw(leaves)))
    return tree


# ------------------------------------------------------------------------- URDF

#: Numbers and vectors that are wrong in some way (each token of an attribute).
BAD_NUMBERS = ["", " ", "abc", "nan", "NaN", "inf", "-inf", "+inf", "1e400", "-1e400",
               "1e-400", "1e308", "1e-320", "9" * 1200, "0." + "1" * 1200, "1e99999",
               "0x10", "1_0", "1/2", "pi", "L", "2*atan(1/3)", "１", "1,5", "--1", "1e",
               ".", "e5", "1.5.5", "0b1", "1j", "(1)", "1e-7", "3.14159265358979"]
BAD_VECTORS = ["", "0 0", "1 2 3 4", "0 0 0", "1e-200 1e-200 0", "1e200 1e200 0",
               "1e-160 0 0", "1e160 0 0", "1e-300 1e-300 1e-300", "1 1e-20 0",
               "nan 0 0", "0 inf 0", "1e400 0 0", "1e-400 0 0", "1\t0\n0", " 1  0  0 ",
               "1e308 1e308 1e308", "-0 -0 -1", "0.7071 0.7071 0",
               "0.577350269 0.577350269 0.577350269"]
BAD_KINDS = ["floating", "planar", "REVOLUTE", "", "spherical", "revolute ", "fixed",
             "continuous", "prismatic", "ball", "screw"]

_DECIMALS = st.one_of(
    st.sampled_from(["0", "1", "-1", "0.5", "0.4318", "-0.15005", "1e-3", "2.5E2",
                     "+0.1", ".5", "0.0203"]),
    st.integers(-3, 3).map(str),
    st.floats(-10, 10, allow_nan=False, allow_infinity=False).map(repr))
_ANGLES = st.one_of(
    st.sampled_from(["0", "1.5707963", "-1.5707963267948966", "3.14159265",
                     "0.7853981633974483", "1.5708", "6.283185307179586"]),
    st.floats(-7, 7, allow_nan=False, allow_infinity=False).map(repr))
_AXES = st.one_of(
    st.sampled_from(["0 0 1", "1 0 0", "0 -1 0", "0.6 0.8 0", "0 0 -1"]),
    st.tuples(*[st.floats(-1, 1, allow_nan=False, width=32)] * 3)
    .filter(lambda v: sum(x * x for x in v) > 1e-6)
    .map(lambda v: " ".join(repr(float(x)) for x in v)))  # float-ok: URDF text

Element = tuple  # (tag, {attribute: value}, [children])
_DEEP = "<deep>"  # the tag of an element nested in attrs["depth"] <group> elements


def _serialize(element: Element) -> str:
    tag, attrs, children = element
    if tag == _DEEP:  # many levels, written without recursion
        depth = attrs["depth"]
        return "<group>" * depth + "".join(_serialize(c) for c in children) + \
            "</group>" * depth
    text = "".join(f" {k}={quoteattr(str(v))}" for k, v in attrs.items())
    if not children:
        return f"<{tag}{text}/>"
    return f"<{tag}{text}>{''.join(_serialize(c) for c in children)}</{tag}>"


def document(elements: list[Element], root: str = "robot", name: str | None = "r") -> str:
    """The URDF text of ``elements`` under ``<robot name="r">`` (see the module).

    Example
    -------
    >>> document([], root="model", name=None)
    '<model/>'
    """
    attrs = {"name": name} if name is not None else {}
    return _serialize((root, attrs, elements))


def _joint(name: str, kind: str, parent: str, child: str, xyz: str, rpy: str,
           axis: str | None) -> Element:
    children = [("parent", {"link": parent}, []), ("child", {"link": child}, []),
                ("origin", {"xyz": xyz, "rpy": rpy}, [])]
    if axis is not None:
        children.append(("axis", {"xyz": axis}, []))
    return ("joint", {"name": name, "type": kind}, children)


@st.composite
def urdf_chains(draw) -> tuple[list[Element], list[str]]:
    """A valid chain: links ``l0..ln`` joined by joints ``j1..jn`` of random types,
    origins and axes, in random document order, with some ignored elements."""
    n = draw(st.integers(1, 5))
    links = [f"l{k}" for k in range(n + 1)]
    elements: list[Element] = [("link", {"name": name}, []) for name in links]
    for k in range(1, n + 1):
        kind = draw(st.sampled_from(["revolute", "continuous", "prismatic", "fixed"]))
        joint = _joint(f"j{k}", kind, links[k - 1], links[k], " ".join(
            draw(st.lists(_DECIMALS, min_size=3, max_size=3))), " ".join(
            draw(st.lists(_ANGLES, min_size=3, max_size=3))),
            draw(st.one_of(st.none(), _AXES)))
        if draw(st.booleans()):
            joint[2].append(("limit", {"lower": "-1", "upper": "1", "effort": "1",
                                       "velocity": "1"}, []))
        elements.append(joint)
    if draw(st.booleans()):
        elements.append(("material", {"name": "blue"}, [("color", {"rgba": "0 0 1 1"}, [])]))
    return draw(st.permutations(elements)), links


def _elements_with(elements: list[Element], tag: str) -> list[tuple[list, int]]:
    """``(container, index)`` of every element with ``tag``, at any depth."""
    out = []
    for i, (t, _, children) in enumerate(elements):
        if t == tag:
            out.append((elements, i))
        if t != _DEEP:
            out += _elements_with(children, tag)
    return out


@st.composite
def _urdf_mutation(draw, elements: list[Element], links: list[str]) -> None:
    """Change ``elements`` in place, one way."""
    action = draw(st.sampled_from([
        "attribute", "attribute", "drop_attribute", "drop_element", "duplicate",
        "relink", "relink", "cycle", "mimic", "kind", "many", "deep", "unknown"]))
    every = _elements_with(elements, "joint") + _elements_with(elements, "link")
    for tag in ("origin", "axis", "parent", "child"):
        every += _elements_with(elements, tag)
    if action in ("attribute", "drop_attribute", "drop_element", "duplicate") and every:
        container, i = draw(st.sampled_from(every))
        tag, attrs, children = container[i]
        if action == "drop_element":
            container.pop(i)
        elif action == "duplicate":
            container.insert(i, copy.deepcopy(container[i]))
        elif action == "drop_attribute" and attrs:
            del attrs[draw(st.sampled_from(sorted(attrs)))]
        elif action == "attribute":
            key = draw(st.sampled_from(sorted(attrs) + ["xyz", "rpy", "name", "link"]))
            attrs[key] = draw(st.one_of(
                st.sampled_from(BAD_NUMBERS + BAD_VECTORS), st.sampled_from(links),
                st.lists(st.sampled_from(BAD_NUMBERS), min_size=3, max_size=3)
                .map(" ".join), st.text(max_size=12)))
    elif action == "relink":  # another link as parent or child: loops, two parents
        ends = _elements_with(elements, "parent") + _elements_with(elements, "child")
        if ends:
            container, i = draw(st.sampled_from(ends))
            container[i][1]["link"] = draw(st.sampled_from(links))
    elif action == "cycle":
        k = draw(st.integers(1, 4))
        names = [f"c{i}" for i in range(k)]
        attached = draw(st.booleans())  # reached from the chain, or on its own
        elements += [("link", {"name": n}, []) for n in names]
        for i in range(k):
            elements.append(_joint(f"cj{i}", "fixed", names[i], names[(i + 1) % k],
                                   "0 0 0", "0 0 0", None))
        if attached:
            elements.append(_joint("cj_in", "fixed", draw(st.sampled_from(links)),
                                   names[0], "0 0 0", "0 0 0", None))
    elif action == "mimic":
        joints = _elements_with(elements, "joint")
        if joints:
            container, i = draw(st.sampled_from(joints))
            container[i][2].append(("mimic", {"joint": draw(st.sampled_from(
                ["j1", "j2", "nope", ""])), "multiplier": "2"}, []))
    elif action == "kind":
        joints = _elements_with(elements, "joint")
        if joints:
            container, i = draw(st.sampled_from(joints))
            container[i][1]["type"] = draw(st.sampled_from(BAD_KINDS))
    elif action == "many":  # a long chain of fixed joints after the last link, or links
        count = draw(st.integers(50, 300))
        last = links[-1]
        for k in range(count):
            elements.append(("link", {"name": f"m{k}"}, []))
            if draw(st.booleans()) or k == 0:
                elements.append(_joint(f"mj{k}", "fixed", last, f"m{k}", "0 0 0.1",
                                       "0 0 0", None))
                last = f"m{k}"
    elif action == "deep":  # an element nested very deep (ignored, or hiding a joint)
        inner = (elements.pop() if elements and draw(st.booleans())
                 else ("link", {"name": "deep"}, []))
        elements.append((_DEEP, {"depth": draw(st.integers(1, 3000))}, [inner]))
    else:
        elements.append((draw(st.sampled_from(["gazebo", "transmission", "sensor"])),
                         {"reference": "l0", "x": draw(st.text(max_size=5))}, []))


_DTDS = [
    '<!DOCTYPE robot [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;">'
    '<!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;">]>',
    '<!DOCTYPE robot [<!ENTITY x SYSTEM "file:///etc/passwd">]>',
    '<!DOCTYPE robot SYSTEM "http://127.0.0.1:9/robot.dtd">',
    '<!DOCTYPE robot [<!ENTITY % p SYSTEM "http://127.0.0.1:9/p.dtd"> %p;]>',
    '<!DOCTYPE robot>',
]


@st.composite
def urdf_documents(draw) -> tuple[bytes, str | None]:
    """The bytes of a URDF file (a valid chain, mutated) and a tip link (or None)."""
    elements, links = draw(urdf_chains())
    for _ in range(draw(st.integers(0, 3))):
        draw(_urdf_mutation(elements, links))
    root = draw(st.sampled_from(["robot"] * 8 + ["model", "sdf", "{urn:x}robot"]))
    name = draw(st.sampled_from(["r"] * 4 + [None, "", "x" * 300, "<&>\"'"]))
    text = document(elements, root.replace("{urn:x}", ""), name)
    if root.startswith("{"):
        text = text.replace("<robot ", '<robot xmlns="urn:x" ', 1)
    tip = draw(st.one_of(st.none(), st.sampled_from(links), st.sampled_from(
        ["c0", "c1", "m10", "deep", "nope", ""])))
    how = draw(st.sampled_from(["plain"] * 6 + [
        "truncate", "dtd", "entity", "control", "declaration", "bom", "not_utf8",
        "latin1", "comment"]))
    if how == "truncate":
        text = text[:draw(st.integers(0, max(0, len(text) - 1)))]
    elif how == "dtd":
        text = draw(st.sampled_from(_DTDS)) + text
    elif how == "entity":
        text = _DTDS[0] + text.replace('name="l0"', 'name="&c;"', 1)
    elif how == "control":
        at = draw(st.integers(0, len(text)))
        text = text[:at] + draw(st.sampled_from(["\x00", "\x01", "\x1b", "\ufffe",
                                                 "\ud800"])) + text[at:]
    elif how == "declaration":
        text = draw(st.sampled_from([
            '<?xml version="1.0"?>', '<?xml version="1.0" encoding="latin-1"?>',
            '<?xml version="2.0"?>', '<?xml-stylesheet href="x"?>'])) + text
    elif how == "bom":
        text = "\ufeff" + text
    elif how == "comment":
        text = text.replace("<link", "<!-- a -- b --><link", 1)
    data = text.encode("utf-8", errors="surrogatepass")
    if how == "not_utf8":
        at = draw(st.integers(0, len(data)))
        data = data[:at] + draw(st.sampled_from([b"\xff", b"\xc3", b"\xed\xa0\x80",
                                                 b"\x80\x80"])) + data[at:]
    elif how == "latin1":
        data = text.replace('name="l0"', 'name="l\u00e90"').encode("utf-8").replace(
            b"\xc3\xa9", b"\xe9")
    return data, tip


# --------------------------------------------------------------------------- DH

GOOD_ANGLES = [0, "0", "pi/2", "-pi/2", "pi", "-pi", "2*atan(1/3)", "2*atan(3/4)",
               "2*atan(-2)", "pi/2 + pi", "-pi/2 + 2*atan(1/2)"]
GOOD_LENGTHS = [0, 1, -1, "1/2", "L", "2*L", "L/2 + 1", 0.4318, "0.15005", "-3/7"]
BAD_DH_VALUES = [
    "pi/3", "pi/99991", "1e400", "1e-400", "2*atan(10**999)", "2*atan(1/" + "7" * 999 + ")",
    "atan(1)", "sqrt(2)", "pi*L", "L", "q1", "x", "2*atan(L)", "1.5708", 1.5707963,
    float("nan"), float("inf"), -float("inf"), 10**999, -(10**999), 10**1200,  # float-ok
    "9" * 1001,
    "10**1000", "10**1001", "(L+1)**1000", "L**1001", "1/0", "0/0", "zoo", "oo", "nan",
    "pi/2" + " + pi/2" * 20, "atan(1/2)*2" + " + atan(1/3)*2" * 9, "(" * 60 + "1" + ")" * 60,
    "", " ", "-", "revolute", True, False, None, [], {}, [1, 2], {"theta": 0},
    nested(40), "1e-3", 1e-300, 5e-324, "2*atan(1e-300)", "2*atan(1e300)", "-0", -0.0,
]


def _row(draw, name: str) -> dict:
    kind = draw(st.sampled_from(["revolute", "revolute", "prismatic"]))
    row: dict[str, Any] = {"name": name, "type": kind}
    for key, pool in (("theta", GOOD_ANGLES), ("d", GOOD_LENGTHS), ("a", GOOD_LENGTHS),
                      ("alpha", GOOD_ANGLES)):
        if draw(st.integers(0, 4)):
            row[key] = draw(st.sampled_from(pool))
    if draw(st.integers(0, 5)) == 0:
        row["actuated"] = False
    return row


@st.composite
def dh_arms(draw, name: str, first: int, max_rows: int = 4) -> dict:
    """An arm given by a DH table of 1..max_rows rows ``q<first>, ...``."""
    rows = [_row(draw, f"q{first + k}") for k in range(draw(st.integers(1, max_rows)))]
    arm: dict[str, Any] = {"name": name, "dh": rows}
    convention = draw(st.sampled_from([None, "standard", "modified"]))
    if convention:
        arm["convention"] = convention
    if draw(st.booleans()):
        arm["base"] = {"xyz": draw(st.lists(st.sampled_from(GOOD_LENGTHS), min_size=3,
                                            max_size=3)),
                       "rpy": draw(st.lists(st.sampled_from(GOOD_ANGLES), min_size=3,
                                            max_size=3))}
    return arm


@st.composite
def dh_models(draw, marker: str) -> dict:
    """A model with one or two DH arms and contacts on their links, then mutated
    (bad angles and lengths, wrong types, missing keys, many rows, deep values)."""
    arms = [draw(dh_arms("a1", 1))]
    if draw(st.booleans()):
        arms.append(draw(dh_arms("a2", 10)))
    contacts = []
    for i, arm in enumerate(arms):
        contact: dict[str, Any] = {"name": f"c{i + 1}",
                                   "link": f"{arm['name']}/{len(arm['dh'])}",
                                   "point": [0, 0, draw(st.sampled_from(["1/10", 0, "L"]))],
                                   "normal": [0, 0, 1],
                                   "model": draw(st.sampled_from(["hard", "soft",
                                                                  "complete"]))}
        if draw(st.booleans()):
            contact["frame"] = "link"
        contacts.append(contact)
    model = {"name": "dh", "parameters": ["L"], "arms": arms, "contacts": contacts}
    if draw(st.integers(0, 9)) == 0:  # a long table
        rows = model["arms"][0]["dh"]
        count = draw(st.integers(20, 120))
        angle = draw(st.sampled_from(["pi/2", "2*atan(1/3)", 0,
                                      "2*atan(123456789/987654321)"]))
        rows += [{"name": f"m{k}", "type": "revolute", "a": "1/2", "alpha": angle}
                 for k in range(count)]
        model["contacts"][0]["link"] = f"a1/{len(rows)}"
    leaves = st.one_of(st.sampled_from(BAD_DH_VALUES), st.sampled_from(payloads(marker)),
                       st.sampled_from(GOOD_ANGLES + GOOD_LENGTHS),
                       st.sampled_from(["standard", "modified", "craig", "link", "base",
                                        "a1/1", "a1/0", "a2/1", "revolute", "prismatic"]),
                       st.text(max_size=12), st.integers(-10**6, 10**6))
    if draw(st.integers(0, 4)) == 0:
        return model
    return draw(mutated(model, leaves))


# ------------------------------------------------------------------ report JSON

BAD_POLYNOMIALS = [
    "t_q1**1001", "t_q1**1000", "(t_q1 + t_q2 + L + 1)**200", "(t_q1 + t_q2 + 1)**60",
    "t_q1/t_q2", "1/t_q1", "t_q1**-1", "t_q1^2", "t_q1 == 1", "t_q1 = 1", "1/0",
    "sqrt(t_q1)", "pi*t_q1", "sin(t_q1)", "CRootOf(t_q1**2 - 2, 0)", "t_q1**(1/2)",
    "t_q1**t_q2", "1e999999", "9" * 1001, "t_q1*" * 2000 + "1", "+".join(["t_q1"] * 5000),
    "(" * 60 + "t_q1" + ")" * 60, "t_q3 + 1", "s_q1 + 1", "x", "", " ", "t_q1 +", "nan",
    "oo", "zoo", "I*t_q1", "E", "2**10**10", "10**1000*t_q1", "t_q1**1000*t_q2**1000",
    "(t_q1 - 1)*(t_q1 + 1)", "t_q1 + 1" + "0" * 2000, "t_q1\n+ 1", "t_q1 + 1 # x",
    "__import__", "lambda: 1", "t_q1.real", "t_q1[0]", "{t_q1}", "[t_q1]", "t_q1 if 1 else 0",
]
BAD_WITNESS_VALUES = [
    "pi/3", "2*atan(1e999)", "2*atan(1/" + "3" * 999 + ")", "CRootOf(x**33 - 2, 0)",
    "CRootOf(x**2 - 2, 5)", "CRootOf(x**2 - 2, 0)", "CRootOf(x**2 - 2)", "CRootOf(2, 0)",
    "q1=0", "pi/99991", "1e400", "nan", "oo", "1/0", "-pi/2", "pi", "0", "atan(1)*2",
    "sqrt(2)", "2*atan(sqrt(2))", "10**1000", "L", "t_q1", "", "1" * 5000,
]


def report_leaves(marker: str) -> st.SearchStrategy:
    """Values put into a report: bad texts, huge and odd numbers, deep trees."""
    return st.one_of(
        st.sampled_from(BAD_POLYNOMIALS), st.sampled_from(BAD_WITNESS_VALUES),
        st.sampled_from(payloads(marker)),
        st.sampled_from([10**400, -(10**400), 10**4000, -1, 2**63, 1e308, -0.0, 0.5,
                         float("nan"), float("inf"),  # float-ok: hostile values
                         True, None, [], {}, "", "x" * 100_000,
                         nested(31), nested(40), [[0, 1]], [1, 2, 3], {"Nm": -1},
                         {"Nx": 1}, {"q1": "pi/2"}, {"t_q1": "0"}, ["t_q1 + 1"]]),
        st.integers(-10, 10), st.text(max_size=30))


#: Texts that are valid where an equation goes, but extreme.
EXTREME_POLYNOMIALS = [
    "t_q1**1000 - 1", "t_q1**999*t_q2 + 1", "(t_q1 + t_q2 + 1)**40", "10**999*t_q1 - 1",
    "t_q1/" + "7" * 999 + " - 1", "t_q1 - 1/3", "0", "1", "-t_q2", "t_q1*t_q2*L - L**2",
    "s_q1 + 1", "s_q1*t_q2", " + ".join(f"{k}*t_q1**{k}" for k in range(300)),
    "(t_q1 - 1)**2*(t_q2 + 3)", "t_q1**2 + 1", "(((t_q1)))", "t_q1 -  -1",
]


@st.composite
def report_entries_changed(draw, base: dict, marker: str) -> dict:
    """``base`` (a locus report) with 1..4 of its expressions, names or counts replaced:
    the structure stays valid, so that what is read back is used (rendered, verified)."""
    tree = copy.deepcopy(base)
    texts = st.one_of(st.sampled_from(EXTREME_POLYNOMIALS), st.sampled_from(BAD_POLYNOMIALS),
                      st.sampled_from(BAD_WITNESS_VALUES), st.sampled_from(payloads(marker)),
                      st.text(max_size=20))
    counts = st.one_of(st.integers(-2, 12), st.sampled_from([10**400, 2**63, 10**1000]))
    for _ in range(draw(st.integers(1, 4))):
        k = draw(st.integers(0, len(tree["components"]) - 1))
        component = tree["components"][k]
        where = draw(st.sampled_from(["equation", "equation", "witness", "witness", "fixed",
                                      "variable", "number", "parent", "depth", "condition",
                                      "meaning", "float_point", "system"]))
        if where == "equation" and component["equations"]:
            i = draw(st.integers(0, len(component["equations"]) - 1))
            component["equations"][i] = draw(st.one_of(
                st.sampled_from(EXTREME_POLYNOMIALS), texts))
        elif where == "witness":
            witness = component.get("witness") or {}
            witness[draw(st.sampled_from(["q1", "q2", "L", "q9", "t_q1", "pi"]))] = draw(
                texts)
            component["witness"] = witness
        elif where == "fixed":
            tree["fixed"] = draw(st.sampled_from(["", "L=1", "L=0", "L=-1", "L=10**999",
                                                  "L=1,L=2", "L=1/0", "q1=pi/3", "M=1"]))
        elif where == "variable":
            i = draw(st.integers(0, len(tree["variables"]) - 1))
            tree["variables"][i] = draw(st.sampled_from(["t_q1", "t_q2", "t_q3", "L",
                                                         "s_q1", "x", "pi", "t_q1**2"]))
        elif where == "number":
            name = draw(st.sampled_from(["Nm", "Nc", "Ni", "Nr", "Ng", "Nd", "Nh"]))
            (component["numbers"] if draw(st.booleans()) else tree["generic"])[name] = \
                draw(counts)
        elif where in ("parent", "depth"):
            component[where] = draw(counts)
        elif where in ("condition", "meaning", "system"):
            value = draw(st.one_of(texts, st.sampled_from(
                ["<script>alert(1)</script>", "\\input{/etc/passwd}", "$$\\x$$",
                 "```\n# x", "](javascript:x)", "x" * 100_000])))
            if where == "meaning":
                component["meaning"] = [value]
            elif where == "system":
                tree["system"] = value
            else:
                component["condition"] = value
        elif component.get("float_checks"):
            point = component["float_checks"][0]["point"]
            point[draw(st.sampled_from(sorted(point) + ["q9"]))] = draw(texts)
    return tree


# -------------------------------------------------------------------- expressions

_ATOMS = ["0", "1", "2", "7", "10", "0.5", "1e-3", "1e300", "1e-300", "9" * 400, "1e999",
          "t", "s", "L", "pi", "x", "E", "I", "oo", "nan", "__class__", ".5", "5.", "00"]


@st.composite
def expressions(draw, depth: int = 4) -> str:
    """Random text in (and just outside) the parser's grammar: numbers, names, pi,
    atan, sqrt, Rational, Integer, CRootOf, unknown functions, + - * / ** ^, brackets,
    large exponents and nesting."""
    if depth == 0 or draw(st.integers(0, 3)) == 0:
        return draw(st.sampled_from(_ATOMS))
    kind = draw(st.sampled_from(["binary", "binary", "power", "call", "unary", "paren",
                                 "junk"]))
    inner = expressions(depth - 1)
    if kind == "binary":
        op = draw(st.sampled_from(["+", "-", "*", "/", " + ", "*-"]))
        return draw(inner) + op + draw(inner)
    if kind == "power":
        exponent = draw(st.sampled_from(["2", "3", "-1", "-2", "1000", "1001", "999999",
                                         "0.5", "(1/2)", "t", "-0", "2**3"]))
        return f"({draw(inner)})" + draw(st.sampled_from(["**", "^"])) + exponent
    if kind == "call":
        name = draw(st.sampled_from(["atan", "sqrt", "Rational", "Integer", "CRootOf",
                                     "sin", "exp", "eval", "atan"]))
        args = draw(st.lists(inner, min_size=1, max_size=2))
        return f"{name}({', '.join(args)})"
    if kind == "unary":
        return draw(st.sampled_from(["-", "+", "--", "- -"])) + draw(inner)
    if kind == "paren":
        return "(" * draw(st.integers(1, 60)) + draw(inner) + ")" * draw(st.integers(0, 60))
    return draw(inner) + draw(st.sampled_from(["", ")", "(", ",", "=", ";", "'", "\\n",
                                               "\\x00", "[0]", ".real", " if 1 else 0"]))
