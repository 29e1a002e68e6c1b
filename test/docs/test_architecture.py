"""docs/architecture.md lists every tracked file and nothing else (tools/architecture.py --check),
and the check fails, naming them, on a listing with a file that does not exist and one that misses
a tracked file."""
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, 'tools'))
import architecture  # noqa: E402  (tools/ is no package)


def test_the_architecture_page_lists_every_tracked_file_and_no_other():
    run = subprocess.run([sys.executable, os.path.join(ROOT, 'tools', 'architecture.py'), '--check'],
                         cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    assert run.returncode == 0, run.stdout


def test_a_listing_with_a_missing_and_an_extra_file_is_reported_by_name():
    with open(os.path.join(ROOT, architecture.DOC), encoding='utf-8') as f:
        text = f.read()
    files = architecture.tracked_files()
    dropped = 'package.xml'
    assert f'[`{dropped}`](../{dropped})' in text
    fabricated = text.replace(f'- [`{dropped}`](../{dropped}):', '- [`no_such_file.cpp`](../no_such_file.cpp):')
    errors = architecture.check(fabricated, files)
    assert any('no_such_file.cpp' in e and 'not a tracked file' in e for e in errors), errors
    assert any(e.endswith(f'misses the tracked file {dropped}: run tools/architecture.py --write')
               for e in errors), errors


def test_a_glob_line_covers_exactly_the_files_it_matches():
    with open(os.path.join(ROOT, architecture.DOC), encoding='utf-8') as f:
        text = f.read()
    files = architecture.tracked_files()
    messages = [p for p in files if p.startswith('compat/gazebo_msgs/msg/')]
    assert messages and '`compat/gazebo_msgs/msg/*.msg`' in text
    covered = architecture.check(text, files + ['compat/gazebo_msgs/msg/New.msg'])
    assert not any('New.msg' in e for e in covered), covered  # the glob covers it (the count is stale)
    errors = architecture.check(text, files + ['compat/gazebo_msgs/New.txt'])
    assert any('misses the tracked file compat/gazebo_msgs/New.txt' in e for e in errors), errors


def test_a_file_in_no_room_and_a_file_without_description_are_named():
    with open(os.path.join(ROOT, architecture.DOC), encoding='utf-8') as f:
        text = f.read()
    rooms = architecture.read_rooms(text)
    descriptions = architecture.read_descriptions(text)
    _, errors = architecture.listing(['a_new_folder/x.py'], rooms, descriptions)
    assert any(e.startswith('a_new_folder/x.py is in no room') for e in errors), errors


def test_a_new_folder_in_a_room_divided_into_rooms_needs_a_row_of_its_own():
    with open(os.path.join(ROOT, architecture.DOC), encoding='utf-8') as f:
        text = f.read()
    rooms = architecture.read_rooms(text)
    _, errors = architecture.listing(['src/plant/new_room/x.cpp', 'test/new_folder/test_x.py'], rooms, [])
    assert any(e.startswith('src/plant/new_room/x.cpp is in a folder of src/plant/') for e in errors), errors
    assert not any(e.startswith('test/new_folder/test_x.py is in') for e in errors), errors
