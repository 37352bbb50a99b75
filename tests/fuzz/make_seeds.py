#!/usr/bin/env python3
"""Writes the hostile seeds of the fuzz corpora: deep nesting, cycles, huge declared sizes and
numbers at the edges, for every target, so a fuzzer starts next to the attacks of issue 13 instead
of having to grow them byte by byte. Each seed stays under about 12 KB.

    tests/fuzz/make_seeds.py OUT_DIR     writes OUT_DIR/<target>/<seed>

Seeds that still crash a target go to tests/fuzz/pending/<target>/ (see its README) until the fix
lands; the rest are copied into tests/fuzz/corpus/<target>/. Re-running is deterministic.
"""
import gzip
import os
import sys

# pipeline_fuzz's first byte picks the input kind, the second the options (pipeline_fuzz.cpp).
PIPELINE_KINDS = {"fap": 0, "fap.gz": 1, "fba": 2, "mp4": 3, "mimic": 4, "fml": 5, "xmt": 6,
                  "combine": 7}

FAP_MASK = " ".join(["1"] * 68)


def fap(frames, header="2.1 seed 25 {count}\n", count=None):
    """A v2.1 .fap file with the given frame numbers, every FAP present."""
    out = header.format(count=len(frames) if count is None else count)
    for number in frames:
        out += FAP_MASK + "\n" + str(number) + " " + " ".join(["0"] * 68) + "\n"
    return out


def xmto(body):
    return ('<?xml version="1.0"?>\n<XMT-O xmlns="urn:mpeg:mpeg4:xmto:schema:2002"><body>'
            + body + "</body></XMT-O>\n")


def fml(story, model=""):
    return "<fml><model>" + model + "</model><story>" + story + "</story></fml>\n"


ANIMATE = '<animate attributeName="open_jaw" values="0;100;0" dur="1s"/>'
FML_MOVE = '<fap type="open_jaw" val="100" duration="1s"/>'


def seeds():
    s = {}
    # --- the Algebra of Expressions ---
    s["algebra_expression"] = {
        "deep-parens-3000": "(" * 3000 + "a.fap" + ")" * 3000,
        "deep-parens-300": "(" * 300 + "a.fap" + ")" * 300,
        "long-sum-2000": " + ".join(["a.fap"] * 2000),
        "deep-shifts-1500": "a.fap" + " >> 1" * 1500,
        "shift-a-day": "a.fap >> 86400",
        "shift-negative": "a.fap >> -5",
        "shift-huge": "a.fap >> 1e308",
        "priority-2^63": "a.fap@9223372036854775808 | b.fap@1",
        "amplifier-huge": "1e308 * a.fap",
        "amplifier-nan": "nan * a.fap",
        "weight-nan": "a.fap +[nan] b.fap",
    }
    # --- Mimic ---
    s["mimic_compiler"] = {
        "deep-braces-5000": "main " + "{" * 5000 + "jaw <hold=1,value=0.1>;" + "}" * 5000,
        "deep-brackets-300": "main " + "[" * 300 + "jaw <hold=1,value=0.1>;" + "]" * 300,
        "macro-cycle": "def a { b; }\ndef b { a; }\nmain { a; }\n",
        "macro-self": "def a { a; }\nmain { a; }\n",
        "hold-1e9": "main { jaw <hold=1e9,value=0.1>; }\n",
        "hold-1e308": "main { jaw <hold=1e308,value=0.1>; }\n",
        "value-nan": "main { jaw <hold=1,value=nan>; }\n",
        "freq-tiny": "main [ jaw <min=0,max=1,freq=1e-300,duration=1e9>; ]\n",
        "list-times-2^63": "main { jaw ( 0 9223372036854775807; 0 1; ) }\n",
        "defxpr-itself": 'defxpr me "fuzz.mimic"\nmain { me <hold=1,value=1>; }\n',
    }
    # --- .fap text ---
    s["fap_reader"] = {
        "frame-jump-5e7": fap([0, 50000000]),
        "frame-near-2^63": fap([0, 9223372036854775806]),
        "frame-2^63": fap([0, 9223372036854775807]),
        "frame-min-int64": fap([-9223372036854775808, 0]),
        "frame-past-int64": fap([0, 9223372036854775808]),
        "header-count-1e12": fap([0, 1], count=10 ** 12),
        "header-fps-huge": fap([0, 1], header="2.1 seed 1000000000 {count}\n"),
        "values-hostile": "2.1 seed 25 1\n" + FAP_MASK + "\n0 " + " ".join(
            ["9223372036854775807", "-9223372036854775808", "1e308", "nan", "inf"] * 14)[:2000] + "\n",
    }
    # --- FML ---
    s["fml_reader"] = {
        "deep-seq-1000": fml("<act>" + "<seq>" * 1000 + FML_MOVE + "</seq>" * 1000 + "</act>"),
        "deep-par-300": fml("<act>" + "<par>" * 300 + FML_MOVE + "</par>" * 300 + "</act>"),
        "template-cycle": fml('<act><behavior name="a"/></act>',
                              '<template name="a"><behavior name="b"/></template>'
                              '<template name="b"><behavior name="a"/></template>'),
        "talk-itself": fml('<act><talk file="fuzz.fml"/></act>'),
        "duration-1e9": fml('<act><fap type="open_jaw" val="100" duration="1000000000s"/></act>'),
        "repeat-1e9": fml('<act><seq repeat="1000000000">' + FML_MOVE + "</seq></act>"),
        "val-nan": fml('<act><fap type="open_jaw" val="nan" duration="1s"/></act>'),
        "excl-no-branch": fml('<act><excl ev_name="e"><seq ev_val="7">' + FML_MOVE + "</seq></excl></act>",
                              '<event name="e" val="1"/>'),
        "empty-par-beside-timed": fml("<act><par><par/>" + FML_MOVE + "</par></act>"),
        "entities-laughs": '<!DOCTYPE fml [<!ENTITY a "<par/><par/><par/><par/><par/><par/><par/><par/>">'
                           '<!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;"><!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;">'
                           '<!ENTITY d "&c;&c;&c;&c;&c;&c;&c;&c;">]>'
                           + fml("<act><seq>&d;</seq></act>"),
    }
    # --- XMT-Omega ---
    values = ";".join(str(i % 200) for i in range(5000))
    s["xmto_reader"] = {
        "deep-par-1000": xmto("<par>" * 1000 + ANIMATE + "</par>" * 1000),
        "deep-seq-300": xmto("<seq>" * 300 + ANIMATE + "</seq>" * 300),
        "values-5000": xmto('<animate attributeName="open_jaw" values="' + values + '" dur="10s"/>'),
        "includes-itself": xmto('<animation src="fuzz.xmt"/>'),
        "dur-a-million-hours": xmto('<animate attributeName="open_jaw" values="0;1" dur="1000000h"/>'),
        "repeat-count-1e9": xmto('<animate attributeName="open_jaw" values="0;1" dur="1s" repeatCount="1000000000"/>'),
        "dur-nan": xmto('<animate attributeName="open_jaw" values="0;1" dur="nans"/>'),
        "values-huge": xmto('<animate attributeName="open_jaw" values="0;1e308;-1e308;1e999" dur="1s"/>'),
        "begin-2^63": xmto('<animate attributeName="open_jaw" values="0;1" begin="9223372036854775807s" dur="1s"/>'),
    }
    # --- fapc validate (Xerces) ---
    xmta_deep = ('<XMT-A xmlns="urn:mpeg:mpeg4:xmta:schema:2002"><Body><Replace><Scene>'
                 + "<Group><children>" * 400 + "</children></Group>" * 400
                 + "</Scene></Replace></Body></XMT-A>\n")
    s["xml_validation"] = {
        "xmto-values-5000": s["xmto_reader"]["values-5000"],
        "xmto-deep-par-1000": s["xmto_reader"]["deep-par-1000"],
        "fml-deep-seq-1000": s["fml_reader"]["deep-seq-1000"],
        "fml-entities-laughs": s["fml_reader"]["entities-laughs"],
        "xmta-deep-group-400": xmta_deep,
        "external-dtd": '<!DOCTYPE fml SYSTEM "/etc/passwd">' + fml("<act>" + FML_MOVE + "</act>"),
        "external-entity": '<!DOCTYPE fml [<!ENTITY x SYSTEM "file:///etc/passwd">]>'
                           + fml("<act>&x;</act>"),
        "schema-location": xmto("").replace('schema:2002"', 'schema:2002" xmlns:xsi='
                                            '"http://www.w3.org/2001/XMLSchema-instance" '
                                            'xsi:schemaLocation="urn:x http://example.invalid/x.xsd"'),
    }
    # --- the whole pipeline: every input kind, includes naming the input itself (in.<ext>) ---
    def pipe(kind, text, options=0):
        data = text.encode() if isinstance(text, str) else text
        return bytes([PIPELINE_KINDS[kind], options]) + data
    s["pipeline"] = {
        "combine-itself": pipe("combine", "in.combine"),
        "combine-itself-deep": pipe("combine", "(" * 50 + "in.combine" + ")" * 50),
        "combine-absolute-operand": pipe("combine", "/dev/null"),
        "combine-parent-operand": pipe("combine", "../../../../etc/hostname"),
        "combine-folder-operand": pipe("combine", "."),
        "xmt-includes-itself": pipe("xmt", s["xmto_reader"]["includes-itself"].replace("fuzz.xmt", "in.xmt")),
        "xmt-includes-folder": pipe("xmt", xmto('<animation src="."/>')),
        "mimic-defxpr-itself": pipe("mimic", 'defxpr me "in.mimic"\nmain { me <hold=1,value=1>; }\n'),
        "mimic-defxpr-folder": pipe("mimic", 'defxpr me "."\nmain { me <hold=1,value=1>; }\n'),
        "fml-talk-itself": pipe("fml", s["fml_reader"]["talk-itself"].replace("fuzz.fml", "in.fml")),
        "fml-talk-folder": pipe("fml", fml('<act><talk file="."/></act>')),
        "fap-frame-jump": pipe("fap", s["fap_reader"]["frame-jump-5e7"]),
        "fap-frame-2^63": pipe("fap", s["fap_reader"]["frame-near-2^63"]),
        "fap-gz-bomb": pipe("fap.gz", gzip.compress(b"0" * (8 << 20), 9, mtime=0)),
        "fap-gz-plain": pipe("fap.gz", gzip.compress(fap([0, 1, 2]).encode(), 9, mtime=0)),
        "mimic-hold-1e9": pipe("mimic", s["mimic_compiler"]["hold-1e9"]),
        "mimic-high-rate": pipe("mimic", "main { jaw <hold=100000,value=0.1>; }\n", 3),
        "xmt-a-million-hours": pipe("xmt", s["xmto_reader"]["dur-a-million-hours"]),
        "fml-repeat-1e9": pipe("fml", s["fml_reader"]["repeat-1e9"]),
    }
    # Ordinary inputs too, so the fuzzers start from every kind's real structure.
    here = os.path.dirname(os.path.abspath(__file__))
    top = os.path.dirname(os.path.dirname(here))

    def read(path):
        with open(os.path.join(top, path), "rb") as f:
            return f.read()
    for kind, path in [("fap", "corpus/examples/fap/vreng-joy.fap"),
                       ("fba", "tests/fuzz/corpus/fba_decoder/joy-q1-fit.fba"),
                       ("mp4", "tests/fuzz/corpus/mp4_reader/fapc-written.mp4"),
                       ("mimic", "corpus/examples/mimic/figure3.mimic"),
                       ("fml", "corpus/examples/fml/figure8.fml"),
                       ("xmt", "tests/fuzz/corpus/xmto_reader/xmto-values.xmt")]:
        s["pipeline"]["example-" + kind] = pipe(kind, read(path))
    s["pipeline"]["example-fap.gz"] = pipe("fap.gz", gzip.compress(read("corpus/examples/fap/vreng-joy.fap"), mtime=0))
    s["pipeline"]["example-combine"] = pipe("combine", "# a comment\n0.5 * in.fap")
    s["xml_validation"]["example-xmta"] = read("corpus/xmta/gpac-three-tracks.xmt")
    s["xml_validation"]["example-xmto"] = read("tests/fuzz/corpus/xmto_reader/xmto-timing.xmt")
    s["xml_validation"]["example-fml"] = read("corpus/examples/fml/tour.fml")
    return s


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    for target, files in seeds().items():
        folder = os.path.join(sys.argv[1], target)
        os.makedirs(folder, exist_ok=True)
        for name, content in files.items():
            data = content.encode() if isinstance(content, str) else content
            prefix = "" if name.startswith("example-") else "hostile-"
            with open(os.path.join(folder, prefix + name), "wb") as out:
                out.write(data)


if __name__ == "__main__":
    main()
