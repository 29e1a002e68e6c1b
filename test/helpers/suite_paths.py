"""Where the suite's files are, named once for the rooms of test/ (whose depth differs) and for the
programs the tests start."""
import os

HELPERS = os.path.dirname(os.path.abspath(__file__))  # test/helpers: the shared helpers and the harness
TEST_DIR = os.path.dirname(HELPERS)  # test/: the rooms, fixtures/, data/, scripts/, the rostest files
REPOSITORY = os.path.dirname(TEST_DIR)
FIXTURES = os.path.join(TEST_DIR, 'fixtures')
