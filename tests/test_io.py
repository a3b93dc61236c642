"""pendsym.io: atomic writes."""
from pendsym.io import content_hash, write_atomic


def test_write_atomic_creates_replaces_and_reports_no_change(tmp_path):
    p = tmp_path / "d" / "f.txt"
    assert write_atomic(p, "one\n")
    assert not write_atomic(p, "one\n")
    assert write_atomic(p, "two\n")
    assert p.read_text() == "two\n"
    assert [x.name for x in p.parent.iterdir()] == ["f.txt"]   # no temporary left


def test_content_hash_is_stable():
    assert content_hash("abc") == content_hash("abc") != content_hash("abd")


def test_written_files_get_the_normal_mode(tmp_path):
    import os
    old = os.umask(0o022)
    try:
        p = tmp_path / "f.txt"
        write_atomic(p, "x\n")
        assert p.stat().st_mode & 0o777 == 0o644
    finally:
        os.umask(old)
