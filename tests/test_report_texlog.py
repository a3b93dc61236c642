"""The LaTeX log checker of make report: it fails on an overfull box over 5 pt and on any missing glyph."""
from pendsym.emit import texlog

LOG = r"""This is pdfTeX, Version 3.141592653-2.6-1.40.24 (TeX Live 2022/Debian) (preloaded format=pdflatex 2024.1.1)
**haag1935.tex
(./haag1935.tex
LaTeX2e <2022-11-01> patch level 1
(/usr/share/texlive/texmf-dist/tex/latex/base/article.cls
Document Class: article 2022/07/02 v1.4n Standard LaTeX document class
(/usr/share/texlive/texmf-dist/tex/latex/base/size10.clo))
Overfull \hbox (3.1pt too wide) in paragraph at lines 40--41
[]\T1/cmr/m/n/10 fits, nearly|
{PLANTED_BOX}
(./haag1935.aux) )
Output written on haag1935.pdf (60 pages, 1227000 bytes).
"""

WIDE = "Overfull \\hbox (168.0pt too wide) in paragraph at lines 512--530\n[]\\T1/cmr/m/n/10 kernel|"
MISSING = "Missing character: There is no ^^9d in font cmr10!"


def test_a_clean_log_passes(tmp_path):
    log = tmp_path / "haag1935.log"
    log.write_text(LOG.replace("{PLANTED_BOX}", ""))
    assert texlog.check_log(log) == []           # the 3.1 pt box is within the 5 pt limit
    assert texlog.main([str(log)]) == 0


def test_a_planted_overfull_box_fails_with_its_file_and_line(tmp_path, capsys):
    log = tmp_path / "haag1935.log"
    log.write_text(LOG.replace("{PLANTED_BOX}", WIDE))
    (p,) = texlog.check_log(log)
    assert (p.file, p.line) == ("./haag1935.tex", 512)
    assert "168.0pt too wide" in p.what
    assert texlog.main([str(log)]) == 1
    assert "haag1935.tex:512: overfull \\hbox, 168.0pt too wide" in capsys.readouterr().out


def test_a_planted_missing_glyph_fails(tmp_path):
    log = tmp_path / "cellerier.log"
    log.write_text(LOG.replace("{PLANTED_BOX}", MISSING))
    (p,) = texlog.check_log(log)
    assert "missing glyph" in p.what and "cmr10" in p.what
    assert texlog.main([str(log)]) == 1


def test_a_missing_glyph_as_an_error_gives_its_line(tmp_path):
    """With \\tracinglostchars=3 (as the reports set it) the glyph is an error, at its line."""
    err = '! Missing character: There is no ^^9d ("9D) in font cmr10.\n<to be read again>\n l.217 ...'
    err += "\nl.217 K q = n^2 ^^f0^^9d^^95^^84 q"
    log = tmp_path / "haag1935.log"
    log.write_text(LOG.replace("{PLANTED_BOX}", err))
    (p,) = texlog.check_log(log)
    assert p.line == 217 and "missing glyph" in p.what


def test_an_overfull_vbox_fails():
    text = LOG.replace("{PLANTED_BOX}", "Overfull \\vbox (12.5pt too high) detected at line 88\n")
    (p,) = texlog.problems(text, "x.tex")
    assert p.line == 88 and "vbox" in p.what


def test_the_limit_is_five_points():
    text = LOG.replace("{PLANTED_BOX}", "Overfull \\hbox (5.2pt too wide) detected at line 7\n")
    assert len(texlog.problems(text, "x.tex")) == 1
    assert texlog.problems(text, "x.tex", limit=6) == []


def test_a_message_wrapped_at_79_characters_is_read_whole():
    msg = "Missing character: There is no ^^9d in font ec-lmr10!"
    line = "x" * 79 + "\n" + "y" * 20 + "\n" + msg[:79].ljust(79)[:79]
    text = "(./a.tex\n" + line + "\n"
    wrapped = "(./a.tex\n" + "Overfull \\hbox (20.0pt too wide) in paragraph at lines 1--2 and some more text to wr"
    wrapped = wrapped[:9 + 79] + "\n" + wrapped[9 + 79:] + "ap\n"
    assert "20.0pt" in texlog.problems(wrapped, "a.tex")[0].what
    assert texlog.problems(text, "a.tex")[0].what.startswith("missing glyph")


def test_an_input_file_is_named(tmp_path):
    text = ("(./charbonnier1908.tex\n(../bench/charbonnier1908-period.tex\n"
            "Overfull \\hbox (30.0pt too wide) in paragraph at lines 20--21\n) )\n")
    (p,) = texlog.problems(text, "charbonnier1908.tex")
    assert p.file == "../bench/charbonnier1908-period.tex" and p.line == 20


def test_a_missing_log_is_bad_input(tmp_path):
    assert texlog.main([str(tmp_path / "none.log")]) == 2
