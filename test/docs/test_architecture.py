"""docs/architecture.md lists every tracked file and nothing else (tools/architecture.py --check),
and the check fails, naming them, on a listing with a file that does not exist and one that misses
a tracked file, and on an include or import that the rooms table does not allow."""
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


def _fabricated_tree(root, rows, files):
    """A tiny project in root: a rooms table (returned as the doc's text), a CMakeLists.txt that puts
    include/ and src/ on the include path and builds the module `tianracer_description.fastmod`
    from src/py/, a setup.py with the package in src/, and files {path: text}."""
    (root / 'CMakeLists.txt').write_text(
        'add_library(core src/low/low.cpp src/high/high.cpp)\n'
        'target_include_directories(core PUBLIC include PRIVATE src ${BULLET_INCLUDE_DIRS})\n'
        'pybind11_add_module(fastmod_python src/py/module.cpp)\n'
        'set_target_properties(fastmod_python PROPERTIES OUTPUT_NAME fastmod)\n')
    (root / 'setup.py').write_text("setup(packages=['tianracer_description'], package_dir={'': 'src'})\n")
    for path, text in files.items():
        (root / path).parent.mkdir(parents=True, exist_ok=True)
        (root / path).write_text(text)
    table = '\n'.join(f'| {floor} | `{room}` | a room | {may} |' for floor, room, may in rows)
    text = (f'{architecture.ROOMS_BEGIN}\n| floor | room | what it holds | may include |\n| --- | --- | --- | --- |\n'
            f'{table}\n{architecture.ROOMS_END}\n')
    return text, sorted(files) + ['CMakeLists.txt', 'setup.py']


ROOMS = [(1, 'include/api/', 'nothing; the C++ standard library'),
         (2, 'src/low/', '`include/api/`'),
         (3, 'src/high/', 'every room below'),
         (3, 'src/py/', '`include/api/`; pybind11'),
         (4, 'src/tianracer_description/', '`src/py/`; rospy'),
         (5, 'scripts/', '`src/tianracer_description/`')]


def test_a_lower_floor_including_a_higher_one_is_named_with_its_line_and_the_rule(tmp_path):
    text, files = _fabricated_tree(tmp_path, ROOMS, {
        'include/api/api.h': '#pragma once\n',
        'src/low/low.h': '#pragma once\n#include "api/api.h"\n',
        'src/low/low.cpp': '#include "low.h"\n#include <vector>\n#include "high/high.h"\n'
                           '#include "other_package/x.h"\n',
        'src/high/high.h': '#pragma once\n#include "../low/low.h"\n#include "api/api.h"\n',
        'src/high/high.cpp': '#include "high.h"\n#include "low/low.h"\n'})
    errors = architecture.include_violations(text, files, str(tmp_path))
    assert errors == ['src/low/low.cpp:3 includes src/high/high.h (floor 3): src/low/ (floor 2) may include only '
                      'include/api/, src/low/: include through a room it may, or change its "may include" '
                      f'in the rooms table of {architecture.DOC}'], errors


def test_python_imports_of_the_package_are_held_to_the_rooms_as_includes_are(tmp_path):
    text, files = _fabricated_tree(tmp_path, ROOMS, {
        'src/py/module.cpp': '#include "api/api.h"\n',
        'include/api/api.h': '#pragma once\n',
        'src/tianracer_description/__init__.py': '',
        'src/tianracer_description/helpers.py': 'from . import fastmod\nimport os\n',
        'scripts/run': '#!/usr/bin/python3\nfrom tianracer_description.helpers import thing\n'
                       'from tianracer_description import helpers, fastmod\n'})
    errors = architecture.include_violations(text, files, str(tmp_path))
    assert len(errors) == 1 and errors[0].startswith(
        'scripts/run:3 imports tianracer_description.fastmod from src/py/ (floor 3): scripts/ (floor 5) may '
        'include only src/tianracer_description/, scripts/:'), errors


def test_a_rule_naming_no_room_or_a_room_not_below_is_an_error_of_the_table(tmp_path):
    rows = [(1, 'include/api/', 'nothing'), (2, 'src/low/', '`src/high/`'), (3, 'src/high/', 'the rooms below')]
    text, files = _fabricated_tree(tmp_path, rows, {'src/low/low.cpp': '', 'src/high/high.cpp': ''})
    errors = architecture.include_violations(text, files, str(tmp_path))
    assert any(e.startswith(f'{architecture.DOC}: src/low/ (floor 2) may include src/high/, which is on floor 3')
               for e in errors), errors
    assert any(e.startswith(f"{architecture.DOC}: src/high/ may include 'the rooms below', which is no room")
               for e in errors), errors


def test_the_include_check_reads_this_tree_through_cmakelists_include_path():
    assert architecture.cmake_include_dirs()[:2] == ['include', 'src/plant']
    with open(os.path.join(ROOT, architecture.DOC), encoding='utf-8') as f:
        text = f.read()
    row = ('| 3 | `src/plant/physics/` | the multibody physics, one named function per algorithm '
           '| `include/bullet_plant/` |')
    assert row in text
    narrowed = text.replace(row, row.replace('`include/bullet_plant/` |', 'nothing |'))
    errors = architecture.include_violations(narrowed, architecture.tracked_files())
    assert errors and all(e.startswith('src/plant/physics/') and ' includes include/bullet_plant/' in e
                          for e in errors), errors
