#!/usr/bin/env python3
"""The malformed-input suite of issue 13: hostile inputs of every kind, generated at test time, run
through the real fapc program as an outside user would.

Each case is a small folder of files written by this script (big inputs are generated, never
stored) and one fapc command line run inside it. The expectation sits beside each case below:
its family, the exit status, and the kind of diagnostic. Every case must also finish within the
time limit, stay under 1 GB, leave no file in out/ (when it fails) and print no sanitizer report.

    malformed.py list                        the case names, one a line (CTest registers each)
    malformed.py run NAME... --fapc BIN      run cases; exit 0 when each passes or fails as listed
    malformed.py run-all --fapc BIN          every case, with a summary; --write-failures FILE
                                             writes the failing ones in expected-failures form
    malformed.py show NAME --dir DIR         write a case's files into DIR and print its command

Options of run and run-all: --sanitized (the program was built with ASan/UBSan: memory is capped
with ASAN_OPTIONS instead of an address-space limit), --timeout S (default 10), --timeout-listed S
(default 3: for cases in expected-failures.txt, which only have to show they still fail; keeps a
hang from costing CI 10 s), --work DIR (where case folders go; default a temporary folder,
removed after passing cases).

Cases listed in expected-failures.txt (beside this file) are known defects being fixed: they
pass when they fail as expected and FAIL when they start passing, so the list is emptied as the
fixes land.
"""
import argparse
import gzip
import os
import random
import re
import resource
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time
import zlib
from dataclasses import dataclass, field
from typing import Callable, Dict, List, Optional

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(os.path.dirname(HERE))
MEMORY_LIMIT = 1 << 30  # bytes: the 1 GB per input

DIR = object()    # a file entry that must be a directory
FIFO = object()   # a file entry that must be a named pipe (nobody writes to it)


@dataclass
class Case:
    name: str                  # kind.family.what
    files: Dict[str, object]   # relative path -> str | bytes | DIR | FIFO | callable returning bytes
    args: List[str]            # fapc's arguments, run in the case folder; outputs go to out/
    exit: object = 1           # the status, or a tuple of acceptable ones (0 and 1: either works)
    # "placed": an error FILE:LINE:COL or FILE: byte N naming a file of the case;
    # "named": an error FILE: ... naming a non-empty FILE (what cannot be opened has no place);
    # "warning": success with a placed warning; "none": success, nothing required on stderr.
    diagnostic: str = "placed"
    outputs: List[str] = field(default_factory=list)  # must exist after a success
    on_success: str = "none"   # what a success (when 0 is acceptable) must print: "none" or "warning"
    check: Optional[Callable[[str, str], Optional[str]]] = None  # (folder, stderr) -> problem

    @property
    def kind(self):
        return self.name.split(".")[0]

    @property
    def family(self):
        return self.name.split(".")[1]


def source_bytes(path):
    with open(os.path.join(SOURCE, path), "rb") as f:
        return f.read()


# ---- inputs to start from ------------------------------------------------------------------

FAP_MASK = " ".join(["1"] * 68)


def fap(frames, count=None, fps="25", values=None):
    """A v2.1 .fap text, every FAP in the mask, with these frame numbers."""
    row = " ".join(values or ["0"] * 68)
    out = "2.1 malformed {} {}\n".format(fps, len(frames) if count is None else count)
    for number in frames:
        out += FAP_MASK + "\n" + str(number) + " " + row + "\n"
    return out


def xmto(body):
    return ('<?xml version="1.0"?>\n<XMT-O xmlns="urn:mpeg:mpeg4:xmto:schema:2002">\n<body>\n'
            + body + "\n</body>\n</XMT-O>\n")


def fml(story, model=""):
    return "<fml>\n<model>" + model + "</model>\n<story>\n<act>" + story + "</act>\n</story>\n</fml>\n"


def xmta(scene):
    return ('<?xml version="1.0"?>\n<XMT-A xmlns="urn:mpeg:mpeg4:xmta:schema:2002">\n<Body>'
            "<Replace><Scene>" + scene + "</Scene></Replace></Body>\n</XMT-A>\n")


def mimic(body):
    return "main {\n" + body + "\n}\n"


ANIMATE = '<animate attributeName="open_jaw" values="0;100;0" dur="1s"/>'
MOVE = '<fap type="open_jaw" val="100" duration="1s"/>'
JOY = "corpus/examples/fap/joy.fap"
FBA = "tests/fuzz/corpus/fba_decoder/joy-q1-fit.fba"
MP4 = "tests/fuzz/corpus/mp4_reader/fapc-written.mp4"
PHO = "_ 100\nh 50\n@ 80 50 120\nl 60\n"
PROFILE = "jaw open_jaw 512\n"

# One good input of each kind, written as in.<ext>; `compile in.<ext> -o out/out.fap` succeeds.
GOOD = {
    "fap": lambda: fap([0, 1, 2]),
    "fapgz": lambda: gzip.compress(fap([0, 1, 2]).encode(), mtime=0),
    "fba": lambda: source_bytes(FBA),
    "mp4": lambda: source_bytes(MP4),
    "mimic": lambda: mimic("jaw <hold=1,value=0.1>;"),
    "fml": lambda: fml(MOVE),
    "xmto": lambda: xmto(ANIMATE),
    "combine": lambda: "joy.fap\n",
}
EXT = {"fap": ".fap", "fapgz": ".fap.gz", "fba": ".fba", "mp4": ".mp4", "mimic": ".mimic",
       "fml": ".fml", "xmto": ".xmt", "xmta": ".xmt", "combine": ".combine", "profile": ".profile",
       "pho": ".pho", "validate": ".xmt", "csv": ".csv"}


# Profiles and .pho files are not inputs of their own: a Mimic program or FML document uses them.
MAIN_INPUT = {"profile": "mimic", "pho": "fml"}


def compile_case(name, text, out="out/out.fap", extra=(), **kw):
    """`fapc compile in.<ext> -o OUT` on one input file (plus kw files)."""
    kind = name.split(".")[0]
    kind = MAIN_INPUT.get(kind, kind)
    files = {"in" + EXT[kind]: text}
    files.update(kw.pop("files", {}))
    return Case(name, files, ["compile", "in" + EXT[kind], "-o", out] + list(extra), **kw)


def with_joy(files):
    files = dict(files)
    files["joy.fap"] = lambda: source_bytes(JOY)
    return files


def gzip_bomb(size, unit=b"\n"):
    """A .gz whose member inflates to `size` bytes of `unit` repeated. One megabyte is deflated
    once and ended with a full flush (byte-aligned, no back-references across it), so the same
    compressed block can simply be repeated: a 1 GB bomb costs a CRC, not a deflate of 1 GB."""
    chunk = unit * ((1 << 20) // len(unit))
    compressor = zlib.compressobj(9, zlib.DEFLATED, -15)
    block = compressor.compress(chunk) + compressor.flush(zlib.Z_FULL_FLUSH)
    count = size // len(chunk)
    crc = 0
    for _ in range(count):
        crc = zlib.crc32(chunk, crc)
    final = zlib.compressobj(9, zlib.DEFLATED, -15).flush()  # an empty last block
    header = b"\x1f\x8b\x08\x00\x00\x00\x00\x00\x02\xff"
    trailer = crc.to_bytes(4, "little") + ((count * len(chunk)) & 0xFFFFFFFF).to_bytes(4, "little")
    return header + block * count + final + trailer


def truncated(data, fraction):
    data = data.encode() if isinstance(data, str) else data
    return data[: int(len(data) * fraction)]


def patched(data, offset, new):
    data = bytearray(data)
    data[offset:offset + len(new)] = new
    return bytes(data)


def mp4_boxes(data):
    """(offset, size, type) of every box the MP4 nests (moov, trak, mdia, minf, stbl...)."""
    found = []

    def walk(start, end):
        at = start
        while at + 8 <= end:
            size = int.from_bytes(data[at:at + 4], "big")
            kind = data[at + 4:at + 8].decode("latin-1")
            if size < 8 or at + size > end:
                return
            found.append((at, size, kind))
            if kind in ("moov", "trak", "mdia", "minf", "stbl", "dinf", "udta"):
                walk(at + 8, at + size)
            at += size
    walk(0, len(data))
    return found


def mp4_with(patch):
    def make():
        data = source_bytes(MP4)
        boxes = {kind: (at, size) for at, size, kind in mp4_boxes(data)}
        return patch(data, boxes)
    return make


# ---- the cases, family by family ---------------------------------------------------------------

def not_a_file_cases():
    """A directory, a FIFO, a missing path or a path through a file where a file is expected."""
    cases = []
    for kind in ["fap", "fapgz", "fba", "mp4", "mimic", "fml", "xmto", "combine"]:
        name = "in" + EXT[kind]
        cases.append(Case(kind + ".notfile.input-directory", {name: DIR},
                          ["compile", name, "-o", "out/out.fap"], diagnostic="named"))
        cases.append(Case(kind + ".notfile.input-fifo", {name: FIFO},
                          ["compile", name, "-o", "out/out.fap"], diagnostic="named"))
        cases.append(Case(kind + ".notfile.input-missing", {},
                          ["compile", name, "-o", "out/out.fap"], diagnostic="named"))
        cases.append(Case(kind + ".notfile.input-under-a-file", {"file": "x"},
                          ["compile", "file/" + name, "-o", "out/out.fap"], diagnostic="named"))
    for what, entry in [("directory", DIR), ("fifo", FIFO), ("missing", None)]:
        files = {} if entry is None else {"x.xmt": entry}
        cases.append(Case("validate.notfile." + what, files, ["validate", "x.xmt"],
                          diagnostic="named"))
        # Includes: the error belongs at the element or line naming the file, or to the file.
        inc = {} if entry is None else {"inc": entry}
        cases.append(compile_case("mimic.notfile.defxpr-" + what,
                                  'defxpr smile "inc"\nmain { smile <hold=1,value=1>; }\n',
                                  files=inc, diagnostic="named"))
        cases.append(compile_case("xmto.notfile.animation-src-" + what,
                                  xmto('<animation src="inc"/>'), files=inc, diagnostic="named"))
        # (A talk file that is not .pho is silent with a warning, docs/fml.md: so name a .pho.)
        pho = {} if entry is None else {"inc.pho": entry}
        cases.append(compile_case("pho.notfile.talk-file-" + what, fml('<talk file="inc.pho"/>'),
                                  files=pho, diagnostic="named"))
        cases.append(compile_case("combine.notfile.operand-" + what, "inc\n", files=inc,
                                  diagnostic="named"))
        cases.append(Case("combine.notfile.command-operand-" + what, inc,
                          ["combine", "inc", "-o", "out/out.fap"], diagnostic="named"))
        cases.append(Case("profile.notfile.profile-" + what, dict(inc, **{"in.mimic": GOOD["mimic"]}),
                          ["compile", "in.mimic", "--profile", "inc", "-o", "out/out.fap"],
                          diagnostic="named"))
    return cases


def depth_cases():
    """Nesting past any sane depth: each reader must refuse it with a placed error."""
    cases = []
    for depth in [300, 5000, 100000]:
        d = str(depth)
        # 300 levels may be within a reader's limit (XML readers stop at 256): accepted or refused
        # with a placed error, never a crash. `validate` must refuse what compile refuses.
        may = {"exit": (0, 1)} if depth == 300 else {}
        cases += [
            compile_case("combine.depth.parens-" + d, "(" * depth + "joy.fap" + ")" * depth + "\n",
                         files=with_joy({}), **may),
            compile_case("combine.depth.shifts-" + d, "joy.fap" + " >> 0" * min(depth, 60000) + "\n",
                         files=with_joy({}), exit=(0, 1)),
            compile_case("mimic.depth.braces-" + d,
                         "main " + "{" * depth + "jaw <hold=1,value=0.1>;" + "}" * depth + "\n", **may),
            compile_case("mimic.depth.brackets-" + d,
                         "main " + "[" * depth + "jaw <hold=1,value=0.1>;" + "]" * depth + "\n", **may),
            compile_case("fml.depth.seq-" + d, fml("<seq>" * depth + MOVE + "</seq>" * depth)),
            compile_case("fml.depth.par-" + d, fml("<par>" * depth + MOVE + "</par>" * depth)),
            compile_case("xmto.depth.par-" + d, xmto("<par>" * depth + ANIMATE + "</par>" * depth)),
            compile_case("xmto.depth.seq-" + d, xmto("<seq>" * depth + ANIMATE + "</seq>" * depth)),
            Case("validate.depth.xmto-par-" + d,
                 {"x.xmt": xmto("<par>" * depth + ANIMATE + "</par>" * depth)}, ["validate", "x.xmt"]),
            Case("validate.depth.fml-seq-" + d,
                 {"x.fml": fml("<seq>" * depth + MOVE + "</seq>" * depth)}, ["validate", "x.fml"]),
            Case("validate.depth.xmta-group-" + d,
                 {"x.xmt": xmta("<Group><children>" * depth + "</children></Group>" * depth)},
                 ["validate", "x.xmt"]),
        ]
    # `fapc combine` takes the expression on the command line (at most 128 KB per argument).
    cases.append(Case("combine.depth.command-parens-30000", with_joy({}),
                      ["combine", "(" * 30000 + "joy.fap" + ")" * 30000, "-o", "out/out.fap"],
                      diagnostic="named"))
    # Templates calling templates, each one deeper.
    chain = "".join('<template name="t{}"><behavior name="t{}"/></template>'.format(i, i + 1)
                    for i in range(5000)) + '<template name="t5000">' + MOVE + "</template>"
    cases.append(compile_case("fml.depth.template-chain-5000", fml('<behavior name="t0"/>', chain)))
    macros = "".join("def m{} {{ m{}; }}\n".format(i, i + 1) for i in range(5000))
    cases.append(compile_case("mimic.depth.macro-chain-5000",
                              macros + "def m5000 { jaw <hold=1,value=0.1>; }\nmain { m0; }\n"))
    return cases


def cycle_cases():
    cases = [
        compile_case("combine.cycle.itself", "in.combine\n"),
        compile_case("combine.cycle.two", "b.combine\n", files={"b.combine": "in.combine\n"}),
        compile_case("combine.cycle.three", "b.combine + joy.fap\n",
                     files=with_joy({"b.combine": "c.combine\n", "c.combine": "(in.combine)\n"})),
        compile_case("combine.cycle.through-folder", "sub/b.combine\n",
                     files={"sub/b.combine": "../in.combine\n"}),
        Case("combine.cycle.command", {"a.combine": "a.combine\n"},
             ["combine", "a.combine", "-o", "out/out.fap"]),
        compile_case("xmto.cycle.itself", xmto('<animation src="in.xmt"/>')),
        compile_case("xmto.cycle.two", xmto('<animation src="b.xmt"/>'),
                     files={"b.xmt": xmto('<animation src="in.xmt"/>')}),
        compile_case("xmto.cycle.through-combine", xmto('<animation src="b.combine"/>'),
                     files={"b.combine": "in.xmt\n"}),
        compile_case("combine.cycle.through-xmto", "b.xmt\n",
                     files={"b.xmt": xmto('<animation src="in.combine"/>')}),
        compile_case("mimic.cycle.defxpr-itself", 'defxpr me "in.mimic"\nmain { me <hold=1,value=1>; }\n'),
        compile_case("fml.cycle.templates", fml('<behavior name="a"/>',
                                               '<template name="a"><behavior name="b"/></template>'
                                               '<template name="b"><behavior name="a"/></template>')),
        compile_case("mimic.cycle.macros", "def a { b; }\ndef b { a; }\nmain { a; }\n"),
        # Not cycles: the same file twice is fine and must still work.
        compile_case("combine.cycle.diamond-is-fine", "b.combine + c.combine\n",
                     files=with_joy({"b.combine": "joy.fap\n", "c.combine": "joy.fap\n"}),
                     exit=0, diagnostic="none", outputs=["out/out.fap"]),
        compile_case("xmto.cycle.twice-is-fine",
                     xmto('<par><animation src="b.fap"/><animation src="b.fap"/></par>'),
                     files={"b.fap": fap([0, 1])}, exit=0, diagnostic="none",
                     outputs=["out/out.fap"]),
    ]
    return cases


def huge_cases():
    """Small inputs that ask for huge allocations or outputs: refused up front, with the limit."""
    def mp4_stsz_count(data, boxes):
        at, _ = boxes["stsz"]
        return patched(data, at + 16, b"\xff\xff\xff\xf0")  # sample_count after size and flags

    def mp4_box_size(kind, size):
        def patch(data, boxes):
            at, _ = boxes[kind]
            return patched(data, at, size)
        return patch

    def mp4_mdhd_duration(data, boxes):
        at, _ = boxes["mdhd"]
        return patched(data, at + 24, b"\xff\xff\xff\xff")

    cases = [
        compile_case("fap.huge.frame-jump-5e7", fap([0, 50000000])),
        compile_case("fap.huge.frame-jump-2^40", fap([0, 1 << 40])),
        compile_case("fap.huge.frame-jump-encode", fap([0, 50000000]), out="out/out.fba"),
        compile_case("fap.huge.header-fps-1e9", fap([0, 1], fps="1000000000")),
        compile_case("fapgz.huge.bomb-newlines-1g", lambda: gzip_bomb(1 << 30)),
        compile_case("fapgz.huge.bomb-digits-1g", lambda: gzip_bomb(1 << 30, b"0")),
        # gzip allows several members one after the other (zcat reads them all): a bomb in the second.
        compile_case("fapgz.huge.bomb-second-member",
                     lambda: gzip.compress(b"2.1 bomb 25 1\n", mtime=0) + gzip_bomb(1 << 30)),
        compile_case("combine.huge.shift-a-day-1000fps", "joy.fap >> 86400\n", files=with_joy({}),
                     extra=["--fps", "1000"]),
        # The expression is an argument, not a file: its errors are placed as <expression>:1:COL.
        Case("combine.huge.command-shift-a-day", with_joy({}),
             ["combine", "joy.fap >> 86400", "--fps", "1000", "-o", "out/out.fap"], diagnostic="named"),
        compile_case("combine.huge.sum-of-shifts", " + ".join(["(joy.fap >> 86000)"] * 200) + "\n",
                     files=with_joy({})),
        compile_case("fap.huge.header-count-1e12-only-a-warning", fap([0, 1], count=10 ** 12),
                     exit=0, diagnostic="warning", outputs=["out/out.fap"]),
        compile_case("mimic.huge.hold-1e6-1000fps", mimic("jaw <hold=1000000,value=0.1>;"),
                     extra=["--fps", "1000"]),
        compile_case("mimic.huge.hold-1e300", mimic("jaw <hold=1e300,value=0.1>;")),
        compile_case("mimic.huge.periodic-1e9", mimic("[ jaw <min=0,max=0.1,freq=1000,duration=1e9>; ]")),
        compile_case("fml.huge.duration-1e9", fml('<fap type="open_jaw" val="100" duration="1000000000s"/>')),
        compile_case("fml.huge.repeat-1e9", fml('<seq repeat="1000000000">' + MOVE + "</seq>")),
        compile_case("fml.huge.nested-repeats",
                     fml('<seq repeat="1000"><seq repeat="1000"><seq repeat="1000">' + MOVE
                         + "</seq></seq></seq>")),
        compile_case("xmto.huge.dur-a-million-hours",
                     xmto('<animate attributeName="open_jaw" values="0;1" dur="1000000h"/>')),
        compile_case("xmto.huge.repeat-count-1e9",
                     xmto('<animate attributeName="open_jaw" values="0;1" dur="1s" repeatCount="1000000000"/>')),
        compile_case("xmto.huge.values-100000",
                     xmto('<animate attributeName="open_jaw" values="' + ";".join(
                         str(i % 100) for i in range(100000)) + '" dur="1s"/>'),
                     exit=0, diagnostic="none", outputs=["out/out.fap"]),
        Case("validate.huge.values-5000",
             {"x.xmt": xmto('<animate attributeName="open_jaw" values="' + ";".join(
                 str(i % 100) for i in range(5000)) + '" dur="10s"/>')}, ["validate", "x.xmt"],
             exit=0, diagnostic="none"),
        # compile reads this document (xmto.huge.values-100000): validate accepts it too, as fast.
        Case("validate.huge.values-100000",
             {"x.xmt": xmto('<animate attributeName="open_jaw" values="' + ";".join(
                 str(i % 100) for i in range(100000)) + '" dur="10s"/>')}, ["validate", "x.xmt"],
             exit=0, diagnostic="none"),
        compile_case("pho.huge.duration-1e12", fml('<talk file="s.pho"/>'),
                     files={"s.pho": "_ 1000000000000\nh 50\n"}),
        compile_case("mp4.huge.stsz-count", mp4_with(mp4_stsz_count)),
        compile_case("mp4.huge.moov-size", mp4_with(mp4_box_size("moov", b"\xff\xff\xff\xf0"))),
        compile_case("mp4.huge.box-size-64bit",
                     mp4_with(mp4_box_size("moov", b"\x00\x00\x00\x01"))),
        compile_case("mp4.huge.mdhd-duration", mp4_with(mp4_mdhd_duration)),
        # The FBA stream codes 1..255 fps: the refusal belongs to the header's frame rate.
        compile_case("fap.huge.fps-1000-to-mp4", fap(list(range(3)), fps="1000"), out="out/out.mp4"),
    ]
    return cases


def number_cases():
    """Numbers at the edges of every representation: range-checked before any arithmetic."""
    cases = []
    edges = {"2^63-1": "9223372036854775807", "-2^63": "-9223372036854775808",
             "2^63": "9223372036854775808", "1e19": "10000000000000000000", "-1e19": "-10000000000000000000"}
    for label, number in edges.items():
        cases.append(compile_case("fap.numbers.frame-" + label, fap([0, number])))
        cases.append(compile_case("fap.numbers.first-frame-" + label, fap([number])))
    cases.append(compile_case("fap.numbers.frames-both-ends",
                              fap(["-9223372036854775808", "9223372036854775807"])))
    for label, number in [("2^63", "9223372036854775808"), ("1e308", "1e308"), ("nan", "nan"),
                          ("inf", "inf"), ("2^31", "2147483648")]:
        cases.append(compile_case("fap.numbers.value-" + label, fap([0], values=[number] * 68)))
    for label, fps in [("nan", "nan"), ("zero", "0"), ("negative", "-25"), ("1e308", "1e308"),
                       ("2^63", "9223372036854775808")]:
        cases.append(compile_case("fap.numbers.fps-" + label, fap([0, 1], fps=fps)))
    for label, value in [("nan", "nan"), ("inf", "inf"), ("1e308", "1e308"), ("-1e308", "-1e308"),
                         ("1e400", "1e400")]:
        # A finite value out of the FAP's range is clamped with a warning (docs/mimic.md, fml.md).
        clamp = {"exit": 0, "diagnostic": "warning", "outputs": ["out/out.fap"]} if "e308" in label else {}
        cases.append(compile_case("mimic.numbers.value-" + label,
                                  mimic("jaw <hold=1,value={}>;".format(value)), **clamp))
        cases.append(compile_case("mimic.numbers.hold-" + label,
                                  mimic("jaw <hold={},value=0.1>;".format(value))))
        cases.append(compile_case("fml.numbers.val-" + label,
                                  fml('<fap type="open_jaw" val="{}" duration="1s"/>'.format(value)), **clamp))
        cases.append(compile_case("fml.numbers.duration-" + label,
                                  fml('<fap type="open_jaw" val="1" duration="{}s"/>'.format(value))))
        cases.append(compile_case("xmto.numbers.values-" + label,
                                  xmto('<animate attributeName="open_jaw" values="0;{}" dur="1s"/>'.format(value)), **clamp))
        cases.append(compile_case("xmto.numbers.dur-" + label,
                                  xmto('<animate attributeName="open_jaw" values="0;1" dur="{}s"/>'.format(value))))
        cases.append(compile_case("combine.numbers.amplifier-" + label,
                                  "{} * joy.fap\n".format(value), files=with_joy({})))
        cases.append(compile_case("combine.numbers.shift-" + label,
                                  "joy.fap >> {}\n".format(value), files=with_joy({})))
        cases.append(compile_case("combine.numbers.weight-" + label,
                                  "joy.fap +[{}] joy.fap\n".format(value), files=with_joy({})))
        cases.append(compile_case("profile.numbers.scale-" + label, mimic("jaw <hold=1,value=0.5>;"),
                                  files={"p.profile": "jaw open_jaw {}\n".format(value)},
                                  extra=["--profile", "p.profile"], **clamp))
        cases.append(compile_case("pho.numbers.duration-" + label, fml('<talk file="s.pho"/>'),
                                  files={"s.pho": "_ {}\nh 50\n".format(value)}))
    cases.append(compile_case("combine.numbers.priority-2^63",
                              "joy.fap@9223372036854775808 | joy.fap@1\n", files=with_joy({})))
    cases.append(compile_case("xmto.numbers.begin-2^63",
                              xmto('<animate attributeName="open_jaw" values="0;1" begin="9223372036854775807s" dur="1s"/>')))
    cases.append(compile_case("xmto.numbers.keytimes-nan",
                              xmto('<animate attributeName="open_jaw" values="0;1" keyTimes="0;nan" dur="1s"/>')))
    cases.append(compile_case("mimic.numbers.list-time-2^63",
                              mimic("jaw ( 0 9223372036854775807; 0 0.1; )")))
    return cases


def truncation_cases():
    cases = []
    text_inputs = {
        "fap": fap([0, 1, 2]),
        "fml": fml(MOVE),
        "xmto": xmto(ANIMATE),
        "mimic": mimic("jaw <hold=1,value=0.1>;\nhead_rot_x <in=1,value=5>;"),
    }
    for kind, text in text_inputs.items():
        for fraction in [0.1, 0.45, 0.8]:
            cases.append(compile_case("{}.trunc.at-{}".format(kind, int(fraction * 100)),
                                      truncated(text, fraction)))
    # XMT-A scenes are validated (and refused as compile inputs): cut short, they must be placed.
    scene = lambda fraction: (lambda: truncated(source_bytes("corpus/xmta/gpac-three-tracks.xmt"), fraction))
    for fraction in [0.1, 0.5, 0.9]:
        cases.append(Case("xmta.trunc.validate-at-{}".format(int(fraction * 100)),
                          {"x.xmt": scene(fraction)}, ["validate", "x.xmt"]))
        cases.append(compile_case("xmta.trunc.compile-at-{}".format(int(fraction * 100)), scene(fraction)))
    # .fap cut inside a line: the mask line short of 68 entries, a values line short of its mask.
    cases.append(compile_case("fap.trunc.mid-mask", fap([0]).split("\n")[0] + "\n1 1 1 1\n"))
    cases.append(compile_case("fap.trunc.mid-values",
                              "\n".join(fap([0, 1]).split("\n")[:4])[:-60] + "\n"))
    cases.append(compile_case("combine.trunc.operator", "joy.fap +\n", files=with_joy({})))
    cases.append(compile_case("combine.trunc.mask", "joy.fap[mouth\n", files=with_joy({})))
    cases.append(compile_case("combine.trunc.quote", '"joy.fap\n', files=with_joy({})))
    cases.append(compile_case("profile.trunc.line", mimic("jaw <hold=1,value=0.5>;"),
                              files={"p.profile": "jaw open_jaw\n"}, extra=["--profile", "p.profile"]))
    cases.append(compile_case("pho.trunc.line", fml('<talk file="s.pho"/>'),
                              files={"s.pho": "_ 100\nh\n"}))
    gz = gzip.compress(fap([0, 1, 2]).encode(), mtime=0)
    for fraction in [0.05, 0.5, 0.9]:
        cases.append(compile_case("fapgz.trunc.at-{}".format(int(fraction * 100)), truncated(gz, fraction)))
    cases.append(compile_case("fapgz.trunc.bad-crc", gz[:-8] + b"\0\0\0\0" + gz[-4:]))
    cases.append(compile_case("fapgz.trunc.garbage-after", gz + b"garbage"))
    fba = lambda fraction: (lambda: truncated(source_bytes(FBA), fraction))
    for fraction in [0.02, 0.2, 0.5, 0.75, 0.97]:
        cases.append(compile_case("fba.trunc.at-{}".format(int(fraction * 100)), fba(fraction)))
    mp4 = lambda fraction: (lambda: truncated(source_bytes(MP4), fraction))
    for fraction in [0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99]:
        cases.append(compile_case("mp4.trunc.at-{}".format(int(fraction * 100)), mp4(fraction)))
    return cases


def junk_cases():
    """Bytes that are no file of the kind at all: empty, NUL, random, bad UTF-8, one long line."""
    rng = random.Random(13)
    junk = {
        "empty": b"",
        "nul-bytes": b"\0" * 4096,
        "random": bytes(rng.randrange(256) for _ in range(4096)),
        "bad-utf8": b"\xff\xfe\xc3\x28\xa0\xa1" * 100,
        "long-line": b"7" * (1 << 20),
    }
    cases = []
    for kind in ["fap", "fapgz", "fba", "mp4", "mimic", "fml", "xmto", "combine"]:
        for label, data in junk.items():
            # An empty .fap is refused or read as no frames with a warning: either is honest.
            empty_fap = label == "empty" and kind in ("fap", "fapgz")
            either = {"exit": (0, 1), "on_success": "warning"} if empty_fap else {}
            cases.append(compile_case(kind + ".junk." + label, data, **either))
    for label, data in junk.items():
        cases.append(Case("validate.junk." + label, {"x.xmt": data}, ["validate", "x.xmt"]))
        cases.append(compile_case("profile.junk." + label, mimic("jaw <hold=1,value=0.5>;"),
                                  files={"p.profile": data}, extra=["--profile", "p.profile"]))
        cases.append(compile_case("pho.junk." + label, fml('<talk file="s.pho"/>'),
                                  files={"s.pho": data}, exit=0 if label == "empty" else 1,
                                  diagnostic="warning" if label == "empty" else "placed",
                                  outputs=["out/out.fap"] if label == "empty" else []))
    # XMT-A is read by its root element; as an input to compile it is refused (docs/cli.md).
    cases.append(compile_case("xmta.junk.scene-as-input", source_bytes("corpus/xmta/gpac-three-tracks.xmt")))
    return cases


def wrong_result_cases():
    """Inputs fapc used to turn into a wrong result, or refuse with a wrong reason."""
    def has_frames(folder, _):
        with open(os.path.join(folder, "out/out.fap")) as f:
            lines = [line for line in f if line.strip() and not line.startswith("#")]
        return None if len(lines) > 3 else "out/out.fap holds no frames"
    return [
        compile_case("combine.wrong.negative-shift", "joy.fap >> -5\n", files=with_joy({})),
        Case("combine.wrong.command-negative-shift", with_joy({}),
             ["combine", "joy.fap >> -5", "-o", "out/out.fap"], diagnostic="named"),
        compile_case("fml.wrong.empty-par-beside-timed", fml("<par><par/>" + MOVE + "</par>"),
                     exit=0, diagnostic="none", outputs=["out/out.fap"], check=has_frames),
        compile_case("xmto.wrong.empty-par-beside-timed", xmto("<par><par/>" + ANIMATE + "</par>"),
                     exit=0, diagnostic="none", outputs=["out/out.fap"], check=has_frames),
        compile_case("fml.wrong.excl-no-matching-branch",
                     fml('<excl ev_name="e"><seq ev_val="7">' + MOVE + "</seq></excl>" + MOVE,
                         '<event name="e" val="1"/>'),
                     exit=0, diagnostic="warning", outputs=["out/out.fap"]),
    ]


def diagnostic_cases():
    """Errors that must name the input and a place in it (not an empty name, not the output)."""
    def empty_fba_track(data, boxes):
        at, _ = boxes["stsz"]
        return patched(data, at + 16, b"\0\0\0\0")
    return [
        compile_case("mp4.diag.fba-track-without-samples", mp4_with(empty_fba_track)),
        compile_case("mimic.diag.too-long-to-render", mimic("jaw <hold=100000000,value=0.1>;")),
        compile_case("fml.diag.too-long-to-render",
                     fml('<fap type="open_jaw" val="1" duration="100000000s"/>')),
        compile_case("fap.diag.encoder-refuses-gap", fap([0, 2000000]), out="out/out.fba"),
        compile_case("fap.diag.frames-not-ascending", fap([5, 3]), out="out/out.fba"),
        # One line of 256 KB: the caret line shows a window around the column, not the line.
        compile_case("mimic.diag.long-line-caret", mimic("jaw" + " " * (1 << 18) + "@"),
                     check=bounded_caret),
        compile_case("xmto.diag.long-line-caret",
                     xmto('<animate attributeName="open_jaw"' + " " * (1 << 18) + 'values="0;1" dur="x"/>'),
                     check=bounded_caret),
    ]


def bounded_caret(_, stderr):
    """The error's source excerpt is a window (docs/cli.md, the Diagnostics rule), the caret under it."""
    if len(stderr) > 2000:
        return "stderr holds {} bytes: the whole source line was printed".format(len(stderr))
    if "^" not in stderr:
        return "no caret under the error"
    return None


def batch_cases():
    def summary(folder, stderr):
        good = os.path.exists(os.path.join(folder, "out", "good.fap"))
        return None if good else "batch stopped before converting the good input"
    bad = "main " + "{" * 100000 + "jaw <hold=1,value=0.1>;" + "}" * 100000 + "\n"
    return [
        Case("batch.crash.one-bad-input", {"in/good.mimic": GOOD["mimic"], "in/bad.mimic": bad},
             ["batch", "in", "-o", "out", "--to", "fap", "--keep-going"], diagnostic="placed",
             check=summary),
        Case("batch.notfile.output-is-a-file", {"in/good.mimic": GOOD["mimic"], "taken": "x"},
             ["batch", "in", "-o", "taken", "--to", "fap"], exit=2, diagnostic="named"),
    ]


def names(file):
    """A check: an error names `file` (the input), not the output."""
    return lambda _, err: None if re.search("^" + re.escape(file) + r": error: ", err, re.M) else \
        "no error names " + file


def no_audio_cases():
    """Issue 32: an input without audio asked for a .wav has nothing to point at: the error names
    the input (docs/speech.md), in compile and in batch alike."""
    return [
        compile_case("xmto.speech.no-audio-to-wav", xmto(ANIMATE), out="out/out.wav", diagnostic="named",
                     check=names("in.xmt")),
        Case("batch.speech.no-audio-to-wav", {"in/a.xmt": xmto(ANIMATE)},
             ["batch", "in", "-o", "out", "--to", "wav"], diagnostic="named", check=names("in/a.xmt")),
    ]


def batch_placed_cases():
    """Issue 32: batch places each input's content error as compile does, on standard error and in
    both reports (docs/json.md: a job's error is a diagnostic with its line and column, or byte)."""
    def reports_placed(folder, stderr):
        import json
        import xml.etree.ElementTree as ET
        with open(os.path.join(folder, "r.json")) as f:
            jobs = json.load(f)["jobs"]
        for job in jobs:
            e = job["error"]
            if not e or not (e["line"] and e["column"] or e["byte"] is not None):
                return "the JSON report's error of {} has no place: {}".format(job["input"], e)
        for case in ET.parse(os.path.join(folder, "r.xml")).getroot().iter("testcase"):
            failure = case.find("failure")
            if failure is None or not ERROR_PLACED.match(failure.get("message")):
                return "the JUnit report's failure of {} has no place".format(case.get("name"))
        return None
    def cut(path, fraction):
        return lambda: truncated(source_bytes(path), fraction)
    files = {"in/a.mimic": mimic("jaw <hold=1,value=0.1>;\n@"), "in/b.fml": fml('<fap type="open_jaw" val="x"/>'),
             "in/c.xmt": xmto('<animate attributeName="open_jaw" values="0;100;0" dur="4h"/>'),
             "in/d.fba": cut(FBA, 0.3), "in/e.mp4": cut(MP4, 0.5)}
    return [Case("batch.diag.reports-placed", files,
                 ["batch", "in", "-o", "out", "--to", "webm", "--keep-going", "--report-json", "r.json",
                  "--report", "r.xml"], check=reports_placed)]


def video_length_cases():
    """Issue 32: a short script of hours to a video is refused from its length, at the element that
    ends it, before its frames are rendered (1.7 s and 350 MB for four hours before); so is a .fap
    whose frame numbers span hours (at the file: its frames are read already)."""
    four_hours = xmto('<animate attributeName="open_jaw" values="0;100;0" dur="4h"/>')
    long_hold = mimic("jaw <hold=30000,value=0.1>;")
    return [
        compile_case("xmto.huge.video-four-hours-webm", four_hours, out="out/out.webm"),
        compile_case("xmto.huge.video-four-hours-html", four_hours, out="out/out.html"),
        Case("xmto.huge.render-four-hours", {"in.xmt": four_hours}, ["render", "in.xmt", "-o", "out/out.webm"]),
        compile_case("mimic.huge.video-past-four-hours", long_hold, out="out/out.webm"),
        compile_case("fap.huge.video-frames-1e5", fap([0, 100000]), out="out/out.webm", diagnostic="named",
                     check=names("in.fap")),
        Case("batch.huge.video-four-hours", {"in/long.xmt": four_hours}, ["batch", "in", "-o", "out", "--to", "webm"]),
    ]


def csv_cases():
    """OpenFace and ARKit CSVs (docs/bridges.md): junk, numbers, sizes, and rows cut short."""
    openface = "frame, timestamp, confidence, success, pose_Rx, AU26_r\n"
    arkit = "Timecode,BlendShapeCount,JawOpen\n"
    rng = random.Random(28)
    cases = [
        compile_case("csv.junk.empty", b""),
        compile_case("csv.junk.nul-bytes", b"\0" * 4096),
        compile_case("csv.junk.random", bytes(rng.randrange(256) for _ in range(4096))),
        compile_case("csv.junk.long-line", b"7" * (1 << 20)),
        compile_case("csv.junk.header-only", openface),
        compile_case("csv.junk.wide-header", "timestamp," + ",".join("c%d" % i for i in range(100000)) + "\n"),
        compile_case("csv.trunc.short-row", openface + "1, 0, 0.9, 1, 0.1, 2\n2, 0.04, 0.9\n"),
        compile_case("csv.trunc.timecode", arkit + "10:00:00:00.000,3,0.5\n10:00:0\n"),
        compile_case("csv.huge.day-long", openface + "1, 0, 0.9, 1, 0, 1\n2, 86400, 0.9, 1, 0, 1\n",
                     extra=["--fps", "1000"]),
        compile_case("csv.huge.timestamp-1e308", openface + "1, 0, 0.9, 1, 0, 1\n2, 1e308, 0.9, 1, 0, 1\n"),
        compile_case("csv.wrong.time-goes-back", openface + "1, 5, 0.9, 1, 0, 1\n2, 4, 0.9, 1, 0, 1\n"),
        compile_case("csv.diag.frames-csv", "frame,time_s,open_jaw\n0,0,100\n"),
    ]
    for label, number in [("nan", "nan"), ("inf", "inf"), ("huge", "1e999"), ("word", "x"), ("2^63", "9223372036854775808")]:
        cases.append(compile_case("csv.numbers." + label, openface + "1, 0, 0.9, 1, 0, " + number + "\n",
                                  exit=0 if label == "2^63" else 1,
                                  diagnostic="warning" if label == "2^63" else "placed"))
        cases.append(compile_case("csv.numbers.arkit-" + label, arkit + "10:00:00:00.000,3," + number + "\n",
                                  exit=0 if label == "2^63" else 1,
                                  diagnostic="warning" if label == "2^63" else "placed"))
    return cases


def wav(rate, samples, value=1000):
    """A mono 16-bit PCM WAV file of `samples` equal samples at `rate` Hz."""
    data = struct.pack("<h", value) * samples
    return (b"RIFF" + struct.pack("<I", 36 + len(data)) + b"WAVEfmt " + struct.pack("<IHHIIHH", 16, 1, 1, rate, rate * 2, 2, 16)
            + b"data" + struct.pack("<I", len(data)) + data)


# An .mp4 with a voice that starts 1 s after the face (its audio edit list begins with an empty
# edit): `fapc compile` of an FML talk with begin="1".
VOICE_MP4 = "tests/fuzz/corpus/mp4_audio/voice-delayed.mp4"


def mp4_audio_delay(duration):
    """VOICE_MP4 with its audio's empty edit lasting `duration` ticks of the movie's timescale."""
    def make():
        data = bytearray(source_bytes(VOICE_MP4))
        at = 0
        while True:
            at = data.find(b"elst", at + 1)
            if at < 0:
                raise SystemExit(VOICE_MP4 + " has no empty edit")
            box = at - 4
            if data[box + 8] == 0 and data[box + 20:box + 24] == b"\xff\xff\xff\xff":  # version 0, media_time -1
                data[box + 16:box + 20] = duration.to_bytes(4, "big")
                return bytes(data)
    return make


def mp4_audio_box(data, wanted):
    """The offset of box `wanted` inside VOICE_MP4's sound track (the trak whose hdlr says soun)."""
    sound_end = -1
    for at, size, kind in mp4_boxes(data):
        if kind == "trak":
            sound_end = at + size if b"soun" in data[at:at + size] else -1
        elif kind == wanted and at < sound_end:
            return at
    return None


def mp4_audio_damaged(part):
    """VOICE_MP4 with its sound's AudioSpecificConfig made an unknown audio object type
    ("config"), or its first access unit made noise ("unit")."""
    def make():
        data = bytearray(source_bytes(VOICE_MP4))
        if part == "config":
            at = data.find(bytes([0x13, 0x88, 0x56, 0xE5, 0x00]), mp4_audio_box(data, "stsd"))
            data[at:at + 2] = bytes([0xF8, 0x08])  # object type 31 + escape: 63, which no decoder has
        else:
            stco = mp4_audio_box(data, "stco")
            first = int.from_bytes(data[stco + 16:stco + 20], "big")
            stsz = mp4_audio_box(data, "stsz")
            size = int.from_bytes(data[stsz + 20:stsz + 24], "big")
            data[first:first + size] = bytes([0xFF]) * size
        return bytes(data)
    return make


def engine_message_caught(folder, stderr):
    """eSpeak NG's own message comes as fapc's warning at the talk, never as its own line."""
    for line in stderr.splitlines():
        if "Full dictionary is not installed" in line and not re.match(r"^in\.fml:\d+:\d+: warning: ", line):
            return "the speech engine printed its own message: " + line
    if "Full dictionary is not installed" not in stderr:
        return "no warning carries the speech engine's message"
    return None


def speech_placed_cases():
    """Issue 32: audio errors at the <audio> element or the MP4 box or access unit that caused
    them, and the speech engine's own messages as placed warnings."""
    slow = {"slow.wav": lambda: wav(1, 4)}
    return [
        compile_case("xmto.speech.audio-1hz-to-mp4", xmto("<par>\n" + ANIMATE + '\n<audio src="slow.wav"/>\n</par>'),
                     out="out/out.mp4", files=slow),
        compile_case("xmto.speech.audio-1hz-to-xmta", xmto("<par>\n" + ANIMATE + '\n<audio src="slow.wav"/>\n</par>'),
                     out="out/out.xmt", extra=["--to", "xmt"], files=slow),
        compile_case("mp4.speech.aac-config-unknown", mp4_audio_damaged("config"), out="out/out.wav"),
        compile_case("mp4.speech.aac-unit-noise", mp4_audio_damaged("unit"), out="out/out.wav"),
        compile_case("fml.speech.engine-message", fml('<talk lang="be">\u041f\u0440\u044b\u0432\u0456\u0442\u0430\u043d\u043d\u0435</talk>'),
                     out="out/out.wav", exit=0, diagnostic="warning", outputs=["out/out.wav"],
                     check=engine_message_caught),
    ]


def speech_cases():
    """Issue 32: talk text that crashed the speech engine, MBROLA voices, speech and audio sized by
    the timeline (refused up front with their option, placed), and far-apart or repeated recordings."""
    hindi = "---\u0932\u091a\u094d\u091b\u0947\u0926"
    talks = "<seq>" + "<talk>Hello there</talk>" * 10000 + "</seq>"
    def engine_silent(folder, stderr):
        """An MBROLA voice made eSpeak NG start a program and print its own messages."""
        for sign in ("mbrowrap", "mbrola voice file", "mbrola:"):
            if sign in stderr:
                return "the speech engine printed '" + sign + "' (it tried an MBROLA voice)"
        return None
    return [
        compile_case("fml.speech.mbrola-voice", fml('<talk lang="mb-en1">Hello</talk>'), out="out/out.wav",
                     check=engine_silent),
        compile_case("fml.speech.mbrola-voice-upper", fml('<talk lang="MB-fr1">Bonjour</talk>'), out="out/out.wav",
                     check=engine_silent),
        compile_case("fml.speech.stacked-suffixes", fml("<talk>" + "s'" * 220 + "</talk>"), out="out/out.wav",
                     exit=0, diagnostic="none", outputs=["out/out.wav"]),
        compile_case("fml.speech.hyphens-before-devanagari", fml('<talk lang="hi">' + hindi + "</talk>"),
                     out="out/out.wav", exit=0, diagnostic="none", outputs=["out/out.wav"]),
        compile_case("fml.speech.hyphens-20000", fml("<talk>Now " + "-" * 20000 + " then</talk>"), out="out/out.wav",
                     exit=0, diagnostic="none", outputs=["out/out.wav"]),
        compile_case("fml.speech.text-1mb", fml("<talk>" + "Hello there. " * 80000 + "</talk>"), out="out/out.wav"),
        compile_case("fml.speech.words-1e5", fml("<talk>" + "word " * 100000 + "</talk>"), out="out/out.wav"),
        compile_case("fml.speech.talks-10000", fml(talks), out="out/out.wav"),
        compile_case("fml.speech.begin-40000-wav", fml('<talk begin="40000">Hi</talk>'), out="out/out.wav",
                     extra=["--fps", "1"], diagnostic="named"),
        compile_case("fml.speech.repeat-talk-1e5", fml('<seq repeat="100000"><talk>Hello there</talk></seq>'),
                     out="out/out.fap"),
        compile_case("xmto.speech.rates-1hz-384khz",
                     xmto('<par><audio src="slow.wav"/><audio src="fast.wav"/></par>'), out="out/out.wav",
                     files={"slow.wav": lambda: wav(1, 1000), "fast.wav": lambda: wav(384000, 100)}),
        compile_case("xmto.speech.audio-hours-apart",
                     xmto('<par><audio src="a.wav"/><audio src="a.wav" begin="40000s"/></par>'),
                     out="out/out.wav", extra=["--fps", "1"], files={"a.wav": lambda: wav(22050, 100)}),
        # A day of silence before the voice, or the largest edit: a .wav from time 0 is refused up front.
        compile_case("mp4.speech.edit-a-day", mp4_audio_delay(86400 * 1000), out="out/out.wav", diagnostic="named"),
        compile_case("mp4.speech.edit-largest", mp4_audio_delay(0xFFFFFFFF), out="out/out.wav", diagnostic="named"),
        compile_case("xmto.speech.audio-repeat-1e5",
                     xmto('<audio src="a.wav" repeatCount="100000"/>'), out="out/out.fap",
                     files={"a.wav": lambda: wav(22050, 22050)}),
    ]


def output_cases():
    """Issue 32: outputs that are not files (an output is replaced only if it is a regular file),
    a batch whose every job fails (no folder left), and a name of a million letters (the "did you
    mean" search and the quoted name stay bounded)."""
    def no_out_folder(folder, stderr):
        return "the batch left its output folder" if os.path.exists(os.path.join(folder, "made")) else None

    def still_folder(folder, stderr):
        return None if os.path.isdir(os.path.join(folder, "folder")) else "the folder named as output is gone"
    long_name = "q" * 1000000
    return [
        Case("output.notfile.directory", {"in.mimic": GOOD["mimic"], "folder": DIR},
             ["compile", "in.mimic", "-o", "folder", "--to", "fap"], diagnostic="named", check=still_folder),
        Case("output.notfile.directory-webm", {"in.mimic": GOOD["mimic"], "folder": DIR},
             ["render", "in.mimic", "-o", "folder", "--to", "webm"], diagnostic="named", check=still_folder),
        Case("output.notfile.plot-directory", {"in.mimic": GOOD["mimic"], "folder": DIR},
             ["plot", "in.mimic", "-o", "folder", "--to", "svg"], diagnostic="named", check=still_folder),
        Case("batch.notfile.every-job-fails", {"in/a.mimic": GOOD["mimic"], "in/b.fap": GOOD["fap"]},
             ["batch", "in", "-o", "made", "--to", "wav", "--keep-going"], diagnostic="named",
             check=no_out_folder),
        compile_case("mimic.huge.unknown-name-1e6", mimic(long_name + " <hold=1,value=0.1>;")),
        compile_case("mimic.huge.unknown-parameter-1e6", mimic("jaw <" + long_name + "=1>;")),
    ]


def intent_cases():
    """FML-APML and APML (docs/intentions.md), both named .xml and read by their root element."""
    def fml_apml(fml, bml=""):
        return "<fml-apml><bml>" + bml + "</bml><fml>\n" + fml + "\n</fml></fml-apml>\n"

    def case(name, text, args=(), **kw):
        files = {"in.xml": text}
        files.update(kw.pop("files", {}))
        return Case(name, files, ["compile", "in.xml", "-o", "out/out.fap"] + list(args), **kw)

    header = "intention\tvalue\tbehaviour\tname\tamount\tstart\tready\trelax\tend\treason\n"
    beats = "".join('<beat id="b{}" type="x" start="0"/>'.format(i) for i in range(101))
    return [
        case("fmlapml.depth.nested-20000", "<fml-apml><fml>" + "<e>" * 20000 + "</e>" * 20000 + "</fml></fml-apml>"),
        case("apml.depth.nested-20000", "<apml>" + "<emphasis>" * 20000 + "a" + "</emphasis>" * 20000 + "</apml>"),
        case("fmlapml.cycle.references", fml_apml('<a id="a" start="b:start"/><b id="b" start="a:end"/>')),
        case("fmlapml.huge.time-1e300", fml_apml('<emotion id="e" type="joy" start="1e300" end="1e300"/>')),
        case("fmlapml.huge.time-day-long", fml_apml('<emotion id="e" type="joy" start="0" end="86400"/>'),
             ["--fps", "1000"]),
        case("fmlapml.huge.intentions-past-max-runs", fml_apml(beats), ["--max-runs", "100"]),
        case("apml.huge.pause-1e9", '<apml>a <pause sec="1e9"/> b</apml>'),
        case("fmlapml.numbers.importance-nan", fml_apml('<emotion id="e" type="joy" start="0" importance="nan"/>')),
        case("fmlapml.numbers.start-inf", fml_apml('<emotion id="e" type="joy" start="inf"/>')),
        case("apml.numbers.intensity-1e308", '<apml><theme affect="joy" intensity="1e308">a</theme></apml>'),
        case("fmlapml.trunc.half", fml_apml('<emotion id="e" type="joy" start="0" end="1"/>')[:40]),
        case("fmlapml.wrong.unknown-intention-kept", fml_apml('<mystery id="m" type="x" start="0" end="2"/>'),
             exit=0, diagnostic="warning", outputs=["out/out.fap"]),
        case("fmlapml.wrong.mark-that-is-not", fml_apml('<emotion id="e" type="joy" start="s1:tm9"/>',
                                                        '<speech id="s1"><tm id="tm1"/>Hi.</speech>')),
        case("fmlapml.notfile.lexicon-directory", fml_apml('<emotion id="e" type="joy" start="0"/>'),
             ["--lexicon", "lexicon"], files={"lexicon": DIR}, diagnostic="named"),
        case("fmlapml.junk.lexicon-nul", fml_apml('<emotion id="e" type="joy" start="0"/>'),
             ["--lexicon", "l.tsv"], files={"l.tsv": header + "emotion\tjoy\tau\t1\x002\t1\t0\t0.2\t0.8\t1\tr\n"}),
    ]


# Xface SMIL-Agent scripts (docs/smil.md).
EXT["smil"] = ".smil"
SMIL_SPEECH = '<speech id="s">Hello <mark id="m"/>there</speech>'


def smil_cases():
    """SMIL-Agent scripts: deep nesting, repeats and lengths past the limits, numbers out of range,
    recordings that are not files or lie outside the allowed folders, junk and cut texts."""
    with_marks = source_bytes("corpus/smil/copperdong__Xface/Faps/withMarks.smil")
    cases = [
        compile_case("smil.depth.par-100000", "<par>" * 100000 + "</par>" * 100000),
        compile_case("smil.depth.seq-5000", "<seq>" * 5000 + '<action dur="1s"/>' + "</seq>" * 5000),
        compile_case("smil.huge.repeat-1e9", '<seq repeat="1000000000"><action dur="1s"/></seq>'),
        compile_case("smil.huge.repeat-nested-1e5",
                     '<seq repeat="100000"><seq repeat="100000"><action action-type="blink"/></seq></seq>'),
        compile_case("smil.huge.dur-1e8", '<seq><action dur="100000000s"/></seq>'),
        compile_case("smil.huge.speech-text-1mb", "<seq><speech>" + "Hello there. " * 80000 + "</speech></seq>"),
        compile_case("smil.huge.speeches-10000", "<seq>" + "<speech>Hello there</speech>" * 10000 + "</seq>"),
        compile_case("smil.huge.anchored-to-repeated-speech",
                     '<par><seq repeat="100000">' + SMIL_SPEECH + '</seq>'
                     + '<speech-animation affect="Sad" content-id="s" content-begin="m"/></par>', out="out/out.wav"),
        compile_case("smil.huge.recording-repeat-1e5", '<seq repeat="100000"><speech file="a.wav"/></seq>',
                     files={"a.wav": lambda: wav(22050, 22050)}),
        compile_case("smil.wrong.marks-reversed",
                     '<par><speech id="s"><mark id="a"/>One two <mark id="b"/>three</speech>'
                     '<speech-animation affect="Sad" content-id="s" content-begin="b" content-end="a"/></par>'),
        compile_case("smil.wrong.unknown-affect-kept", '<par><speech-animation affect="Bored" dur="2s"/></par>',
                     exit=0, diagnostic="warning", outputs=["out/out.fap"]),
        compile_case("smil.notfile.recording-directory", '<seq><speech file="d.wav"/></seq>', files={"d.wav": DIR}),
        compile_case("smil.notfile.recording-fifo", '<seq><speech file="f.wav"/></seq>', files={"f.wav": FIFO}),
        compile_case("smil.notfile.recording-missing", '<seq><speech file="none.wav"/></seq>'),
        compile_case("smil.notfile.recording-outside", '<seq><speech file="../../outside.wav"/></seq>'),
        compile_case("smil.notfile.recording-not-wav", '<seq><speech file="in.smil"/></seq>'),
        compile_case("smil.junk.empty", ""),
        compile_case("smil.junk.nul-bytes", b"<seq>\0\0\0</seq>"),
        compile_case("smil.junk.random", lambda: bytes(random.Random(29).randrange(256) for _ in range(4096))),
        compile_case("smil.trunc.with-marks-half", with_marks[:len(with_marks) // 2]),
    ]
    for label, number in [("1e308", "1e308"), ("minus-1e308", "-1e308"), ("nan", "nan"), ("inf", "inf")]:
        cases += [
            compile_case("smil.numbers.dur-" + label, '<seq><action dur="' + number + '"/></seq>'),
            compile_case("smil.numbers.begin-" + label, '<seq><action begin="' + number + '" dur="1"/></seq>'),
            compile_case("smil.numbers.intensity-" + label, '<seq><action intensity="' + number + '"/></seq>'),
            compile_case("smil.numbers.repeat-" + label, '<seq repeat="' + number + '"><action/></seq>'),
            compile_case("smil.numbers.pointing-" + label,
                         '<seq><action action-type="pointing" channel="alice-head"><parameter>' + number
                         + '</parameter><parameter>0</parameter><parameter>1</parameter></action></seq>',
                         exit=(0, 1), on_success="warning" if label in ("nan", "inf") else "none",
                         diagnostic="placed"),
        ]
    return cases


# SmartBody/NVBG BML (docs/bml.md, "SmartBody"): recorded speech and its file.
EXT["bml"] = ".bml"


def smartbody_cases():
    """Recorded speech whose file is not a file, lies outside, is not a WAV or is missing (a
    warning), and marks whose times are absurd or out of order."""
    def recorded(marks='<sync id="a" time="0"/>hi<sync id="b" time="0.4"/>', ref="rec"):
        return ('<bml><speech id="s" start="0"><text>' + marks + '</text><description type="audio/x-wav">'
                '<file ref="' + ref + '"/></description></speech>'
                '<lips viseme="BMP" start="0" end="0.2"/></bml>\n')
    return [
        compile_case("bml.notfile.recording-directory", recorded(), files={"rec.wav": DIR}),
        compile_case("bml.notfile.recording-fifo", recorded(), files={"rec.wav": FIFO}),
        compile_case("bml.notfile.recording-missing", recorded(), exit=0, diagnostic="warning",
                     outputs=["out/out.fap"]),
        compile_case("bml.notfile.recording-outside", recorded(ref="../../outside.wav")),
        compile_case("bml.notfile.recording-not-wav", recorded(ref="in.bml")),
        compile_case("bml.huge.recording-samples", recorded(), extra=["--max-audio-samples", "100"],
                     files={"rec.wav": lambda: wav(8000, 8000)}),
        compile_case("bml.huge.recorded-mark-1e300", recorded('<sync id="a" time="1e300"/>hi')),
        compile_case("bml.numbers.recorded-mark-nan", recorded('<sync id="a" time="nan"/>hi')),
        compile_case("bml.wrong.recorded-marks-backwards",
                     recorded('<sync id="a" time="0.5"/>hi<sync id="b" time="0.2"/>')),
    ]


# BML blocks given in order (docs/bml.md, "Several blocks"): a .bmlseq list of documents.
EXT["bmlseq"] = ".bmlseq"


def bml_sequence_cases():
    """Bad composition values, lists whose documents are not files, lie outside or are the list
    itself, times that go back or are absurd, references to blocks not sent before, reused block
    ids, and a list longer than --max-runs allows."""
    def block(ident, body='<head id="n" lexeme="NOD"/>', composition="APPEND"):
        return ('<bml xmlns="http://www.bml-initiative.org/bml/bml-1.0" id="' + ident + '" composition="'
                + composition + '">' + body + '</bml>\n')
    a = {"a.bml": block("a", composition="MERGE")}
    cases = [
        compile_case("bml.wrong.composition-blend", block("a", composition="blend")),
        compile_case("bml.wrong.composition-empty", block("a", composition="")),
        compile_case("bmlseq.junk.empty", ""),
        compile_case("bmlseq.junk.comments-only", "# nothing\n\n"),
        compile_case("bmlseq.junk.nul-bytes", b"a.bml\0\0\n", files=a),
        compile_case("bmlseq.notfile.document-missing", "none.bml\n"),
        compile_case("bmlseq.notfile.document-directory", "d.bml\n", files={"d.bml": DIR}),
        compile_case("bmlseq.notfile.document-fifo", "f.bml\n", files={"f.bml": FIFO}),
        compile_case("bmlseq.notfile.document-outside", "../../outside.bml\n"),
        compile_case("bmlseq.cycle.lists-itself", "in.bmlseq\n"),
        compile_case("bmlseq.wrong.at-backwards", "at 2 a.bml\nat 1 b.bml\n",
                     files=dict(a, **{"b.bml": block("b")})),
        compile_case("bmlseq.wrong.at-without-document", "at 1\n"),
        compile_case("bmlseq.wrong.composition-in-document", "a.bml\nb.bml\n",
                     files=dict(a, **{"b.bml": block("b", composition="blend")})),
        compile_case("bmlseq.wrong.reference-to-later-block", "a.bml\nb.bml\n",
                     files=dict(a, **{"b.bml": block("b", '<head id="n" lexeme="NOD" start="c:n:end"/>')})),
        compile_case("bmlseq.wrong.duplicate-block-id", "a.bml\na.bml\n", files=a),
        compile_case("bmlseq.huge.many-documents", "a.bml\n" * 2000, extra=["--max-runs", "50"],
                     files={"a.bml": '<bml id="a"><head id="n" lexeme="NOD"/></bml>\n'}),
    ]
    for label, number in [("1e308", "1e308"), ("nan", "nan"), ("inf", "inf"), ("minus-1", "-1")]:
        cases.append(compile_case("bmlseq.numbers.at-" + label, "at " + number + " a.bml\n", files=a))
    # Greta's expressivity parameters (docs/bml.md, "Greta references"): -1 to 1, placed.
    for label, number in [("1e308", "1e308"), ("nan", "nan"), ("inf", "inf"), ("2", "2")]:
        cases.append(compile_case("bml.numbers.greta-spc-" + label,
                                  '<bml id="b"><face id="f" start="0" end="1"><description type="gretabml">'
                                  '<reference>affect=joy</reference><SPC.value>' + number
                                  + '</SPC.value></description></face></bml>\n'))
    # Invalid documents of each language fapc validates them in (docs/bml.md, docs/intentions.md,
    # docs/smil.md "Validation"): exit 1, each problem at its line and column.
    for name, text in [("bml-composition", '<bml xmlns="http://www.bml-initiative.org/bml/bml-1.0" id="b" composition="blend"/>\n'),
                       ("bml-au", '<bml id="b">\n<faceFacs id="u" au="120"/></bml>\n'),
                       ("fml-apml-no-start", '<fml-apml><fml>\n<emotion id="e" type="joy"/></fml></fml-apml>\n'),
                       ("apml-pause", '<apml>\n<pause sec="-1"/></apml>\n'),
                       ("smil-mark", '<seq>\n<speech>Hi <mark/></speech></seq>\n')]:
        cases.append(Case("validate.wrong." + name, {"x.xml": text}, ["validate", "x.xml"]))
    return cases


# BML behaviours' own values (docs/bml.md): each refused at the attribute (or the reference that
# cannot hold) with its code, shown by -v.
def bml_value_cases():
    def block(*behaviours):
        return ('<bml xmlns="http://www.bml-initiative.org/bml/bml-1.0" id="b">\n' + "\n".join(behaviours)
                + "\n</bml>\n")

    def refused_at(line, column, code):
        def check(folder, stderr):
            want = "in.bml:%d:%d: error[%s]" % (line, column, code)
            return None if want in stderr else "wanted " + want
        return check

    def case(name, at, *behaviours):
        return compile_case("bml.wrong." + name, block(*behaviours), extra=["-v"], check=refused_at(*at))

    nod = '<head id="h" lexeme="NOD"/>'
    return [
        case("amount-nan", (2, 41, "bml.bad_value"), '<faceLexeme id="f" lexeme="RAISE_BROWS" amount="nan"/>'),
        case("amount-word", (2, 41, "bml.bad_value"), '<faceLexeme id="f" lexeme="RAISE_BROWS" amount="lots"/>'),
        case("side-middle", (2, 26, "bml.bad_value"), '<faceFacs id="f" au="12" side="MIDDLE"/>'),
        case("repetition-fraction", (2, 27, "bml.bad_value"), '<head id="h" lexeme="NOD" repetition="2.5"/>'),
        case("repetition-1e9", (2, 27, "bml.bad_value"), '<head id="h" lexeme="NOD" repetition="1e9"/>'),
        case("reference-no-point", (3, 27, "bml.bad_reference"), nod, '<head id="g" lexeme="NOD" start="h::end"/>'),
        case("reference-unknown", (3, 27, "bml.unknown_reference"), nod, '<head id="g" lexeme="NOD" start="x:end"/>'),
        case("offset-word", (3, 27, "bml.bad_reference"), nod, '<head id="g" lexeme="NOD" start="h:end+x"/>'),
        case("offset-before-block", (3, 27, "bml.constraints_conflict"), '<head id="h" lexeme="NOD" start="0"/>',
             '<head id="g" lexeme="NOD" start="h:start-5"/>'),
        case("chain-cycle", (4, 41, "bml.constraints_conflict"),
             '<faceLexeme id="a" lexeme="RAISE_BROWS" start="c:end"/>',
             '<faceLexeme id="b" lexeme="RAISE_BROWS" start="a:end"/>',
             '<faceLexeme id="c" lexeme="RAISE_BROWS" start="b:end"/>'),
    ]


# Every generator of cases: CTest runs each group as one test (`groups`), which builds only its own
# group's inputs, not the megabytes of every other group's.
GROUPS = (not_a_file_cases, depth_cases, cycle_cases, huge_cases, number_cases, truncation_cases,
          junk_cases, wrong_result_cases, diagnostic_cases, batch_cases, csv_cases, speech_cases,
          output_cases, intent_cases, speech_placed_cases, smil_cases, smartbody_cases,
          video_length_cases, no_audio_cases, batch_placed_cases, bml_sequence_cases, bml_value_cases)


def all_cases(group=None):
    """name -> case, of every group, or of the one named."""
    cases = []
    for generate in GROUPS:
        if group is None or generate.__name__ == group:
            cases += generate()
    if group is not None and not cases:
        raise SystemExit("no group of cases named " + group)
    names = [c.name for c in cases]
    duplicates = {n for n in names if names.count(n) > 1}
    if duplicates:
        raise SystemExit("duplicate case names: " + ", ".join(sorted(duplicates)))
    return {c.name: c for c in cases}


# ---- running a case ------------------------------------------------------------------------------

def write_case(case, folder):
    os.makedirs(os.path.join(folder, "out"), exist_ok=True)
    for path, content in case.files.items():
        full = os.path.join(folder, path)
        os.makedirs(os.path.dirname(full), exist_ok=True)
        if content is DIR:
            os.makedirs(full, exist_ok=True)
        elif content is FIFO:
            os.mkfifo(full)
        else:
            data = content() if callable(content) else content
            with open(full, "wb") as f:
                f.write(data.encode() if isinstance(data, str) else data)


ERROR_PLACED = re.compile(r"^(?P<file>[^\n]+?):(?:(?P<line>\d+):(?P<col>\d+)| byte (?P<byte>\d+)): "
                          r"(?P<severity>error|warning)(?:\[[a-z0-9_.]+\])?: ", re.M)  # -v shows the code
ERROR_NAMED = re.compile(r"^(?P<file>[^\n:][^\n]*?): (?:[^\n]*?: )?error: ", re.M)
SANITIZER = re.compile(r"runtime error:|AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer")


def limit_memory():
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


def run_case(case, fapc, folder, timeout, sanitized):
    """Runs one case in `folder`; returns a list of problems (empty: the case passed)."""
    write_case(case, folder)
    env = dict(os.environ)
    if sanitized:
        # ASan reserves terabytes of address space: cap the resident size and the heap instead.
        env["ASAN_OPTIONS"] = ("hard_rss_limit_mb=1024:malloc_limit_mb=1024:detect_leaks=1:"
                               + env.get("ASAN_OPTIONS", ""))
        env.setdefault("LSAN_OPTIONS", "suppressions=" + os.path.join(SOURCE, ".ci/lsan.supp"))
    started = time.monotonic()
    proc = subprocess.Popen([fapc] + case.args, cwd=folder, env=env, stdin=subprocess.DEVNULL,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            preexec_fn=None if sanitized else limit_memory, start_new_session=True)
    try:
        stdout, stderr = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return ["timed out after {} s (limit {} s)".format(timeout, timeout)]
    elapsed = time.monotonic() - started
    case.elapsed = elapsed
    err = stderr.decode("utf-8", "replace")
    problems = []
    allowed = case.exit if isinstance(case.exit, tuple) else (case.exit,)
    if proc.returncode < 0:
        problems.append("killed by signal {} ({})".format(-proc.returncode,
                                                          signal.Signals(-proc.returncode).name))
    elif proc.returncode not in allowed:
        problems.append("exit status {}, expected {}".format(
            proc.returncode, " or ".join(str(a) for a in allowed)))
    succeeded = proc.returncode == 0
    if SANITIZER.search(err):
        problems.append("sanitizer report")
    if "terminate called" in err or "std::bad_alloc" in err:
        problems.append("uncaught exception")
    if re.search(r"^: |^error: |^warning: ", err, re.M):
        problems.append("a diagnostic with an empty file name")
    expected = case.diagnostic
    if succeeded and len(allowed) > 1:
        expected = "named-warning" if case.on_success == "warning" else "none"
    if expected == "placed" and not succeeded:
        placed = [m for m in ERROR_PLACED.finditer(err) if m.group("severity") == "error"]
        if not any(os.path.exists(os.path.join(folder, m.group("file"))) for m in placed):
            problems.append("no error placed (FILE:LINE:COL or FILE: byte N) in a file of the case")
    elif expected == "named" and not succeeded:
        if not ERROR_NAMED.search(err):
            problems.append("no error naming a file (FILE: ... error:)")
    elif expected == "warning":
        if not any(m.group("severity") == "warning" for m in ERROR_PLACED.finditer(err)):
            problems.append("no placed warning (FILE:LINE:COL: warning:)")
    elif expected == "named-warning":
        if not re.search(r"^[^\n:][^\n]*?: (?:[^\n]*?: )?warning: ", err, re.M):
            problems.append("no warning naming the file")
    out = os.path.join(folder, "out")
    left = sorted(os.listdir(out)) if os.path.isdir(out) else []
    if not succeeded:
        if left and not case.name.startswith("batch."):
            problems.append("files left in out/: " + ", ".join(left))
    else:
        for path in case.outputs:
            if not os.path.exists(os.path.join(folder, path)):
                problems.append(path + " not written")
    if case.check and not problems:
        problem = case.check(folder, err)
        if problem:
            problems.append(problem)
    if problems:
        tail = err.strip().splitlines()[-3:]
        problems.append("after {:.1f} s; stderr ends: {}".format(elapsed, " | ".join(t[:200] for t in tail)))
    return problems


def expected_failures(sanitized):
    """name -> reason, from expected-failures.txt: "NAME  reason" lines, # comments. A name written
    sanitized:NAME (or plain:NAME) is expected to fail only in that build."""
    listed = {}
    with open(os.path.join(HERE, "expected-failures.txt")) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            name, _, reason = line.partition(" ")
            build, _, bare = name.rpartition(":")
            if build and build != ("sanitized" if sanitized else "plain"):
                listed.setdefault(bare, None)  # known, but not expected to fail in this build
                continue
            listed[bare] = reason.strip()
    return listed


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("command", choices=["list", "groups", "run", "run-all", "show"])
    parser.add_argument("names", nargs="*")
    parser.add_argument("--fapc")
    parser.add_argument("--sanitized", action="store_true")
    parser.add_argument("--timeout", type=float, default=10)
    parser.add_argument("--timeout-listed", type=float, default=3)
    parser.add_argument("--work")
    parser.add_argument("--dir")
    parser.add_argument("--write-failures")
    parser.add_argument("--group", help="only the cases of this group (see the command groups)")
    args = parser.parse_args()
    if args.command == "groups":
        print("\n".join(generate.__name__ for generate in GROUPS))
        return 0
    cases = all_cases(args.group)
    if args.command == "list":
        print("\n".join(cases))
        return 0
    if args.command == "show":
        case = cases[args.names[0]]
        write_case(case, args.dir)
        print("cd {} && fapc {}".format(args.dir, " ".join(a if len(a) < 80 else a[:60] + "..." for a in case.args)))
        return 0
    if not args.fapc:
        parser.error("run needs --fapc")
    fapc = os.path.abspath(args.fapc)
    known = expected_failures(args.sanitized)
    unknown = sorted(set(known) - set(cases)) if args.group is None else []
    listed = {name: reason for name, reason in known.items() if reason is not None}
    if unknown:
        print("expected-failures.txt names unknown cases: " + ", ".join(unknown))
        return 1
    names = list(cases) if args.command == "run-all" else args.names
    work = args.work or tempfile.mkdtemp(prefix="fapc-malformed-")
    status, failures, counts = 0, [], {"pass": 0, "xfail": 0, "FAIL": 0, "XPASS": 0}
    for name in names:
        case = cases[name]
        folder = os.path.join(work, name)
        shutil.rmtree(folder, ignore_errors=True)
        # A listed case only has to show it still fails; a fixed one finishes in well under a second.
        timeout = min(args.timeout, args.timeout_listed) if name in listed else args.timeout
        problems = run_case(case, fapc, folder, timeout, args.sanitized)
        if not problems:
            outcome = "XPASS" if name in listed else "pass"
            shutil.rmtree(folder, ignore_errors=True)
        else:
            outcome = "xfail" if name in listed else "FAIL"
            failures.append((name, problems))
        counts[outcome] += 1
        if outcome in ("FAIL", "XPASS"):
            status = 1
        if outcome != "pass" or args.command == "run":
            detail = "; ".join(problems)
            if outcome == "XPASS":
                detail = "passes now: remove it from tests/malformed/expected-failures.txt"
            elif outcome == "xfail":
                detail = "expected failure (" + listed[name] + "): " + detail
            if outcome == "pass":
                detail = "{:.1f} s".format(getattr(case, "elapsed", 0))
            print("{:5} {}  {}".format(outcome, name, detail), flush=True)
    if args.command == "run-all":
        print("{} cases: {}".format(len(names), ", ".join("{} {}".format(v, k) for k, v in counts.items())))
    if args.write_failures:
        with open(args.write_failures, "w") as f:
            for name, problems in failures:
                f.write("{}  {}\n".format(name, problems[0]))
    if not args.work:
        shutil.rmtree(work, ignore_errors=True)
    return status


if __name__ == "__main__":
    sys.exit(main())
