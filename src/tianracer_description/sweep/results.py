"""A sweep's rows: the results file (a CSV flushed row by row, or .parquet with pyarrow at the end),
read back typed; the summary table and the summary plot."""
import csv
import math
import os

import numpy as np

from tianracer_description.sweep.scenarios import FIELD_TYPES, RESULT_FIELDS, RESULT_TYPES, SCENARIO_FIELDS

# Rows of a sweep are numbered by their scenario's place in it: the CSV is in the order they finish.
INDEX_FIELD = 'scenario'
COLUMNS = (INDEX_FIELD,) + SCENARIO_FIELDS + RESULT_FIELDS


class ResultsFile:
    """Where a sweep's rows go: a CSV, each row written and flushed as it comes (floats as repr: they
    read back exactly), or a .parquet file (pyarrow) written whole at the end."""

    def __init__(self, path):
        check_results_path(path)
        self.path = path
        self.rows = []
        self._file = self._writer = None
        if path.endswith('.csv'):
            self._file = open(path, 'w', newline='')
            self._writer = csv.DictWriter(self._file, COLUMNS)
            self._writer.writeheader()
            self._file.flush()

    def write(self, row):
        self.rows.append(row)
        if self._writer:
            self._writer.writerow(row)
            self._file.flush()

    def close(self):
        if self._file:
            self._file.close()
        else:
            import pandas
            pandas.DataFrame(self.rows, columns=list(COLUMNS)).to_parquet(self.path)


def check_results_path(path):
    if path.endswith('.parquet'):
        try:
            import pyarrow  # noqa: F401
        except ImportError:
            raise ValueError('%s: writing .parquet needs pyarrow, which is not installed: install it '
                             '(/usr/bin/python3 -m pip install pyarrow) or write a .csv' % path) from None
    elif not path.endswith('.csv'):
        raise ValueError('%s: results are written as .csv (or .parquet with pyarrow)' % path)


def read_results(path):
    """A sweep's CSV as rows of typed values (the types it was written with)."""
    types = dict(FIELD_TYPES, **RESULT_TYPES, **{INDEX_FIELD: int})
    with open(path, newline='') as f:
        return [{name: parse(types[name], text) for name, text in row.items()} for row in csv.DictReader(f)]


def parse(kind, text):
    if kind is bool:
        return text == 'True'
    if kind is str or text == '':
        return text
    return kind(text)


def scenario_of(row):
    """The scenario a row is the result of."""
    return {field: row[field] for field in SCENARIO_FIELDS}


def summary(rows):
    """The sweep in one table: scenarios, failed (an error), crashes and mean laps of those that ran."""
    ran = [row for row in rows if not row['error']]
    laps = [row['laps'] for row in ran]
    lap_times = [row['lap_time'] for row in ran if not math.isnan(row['lap_time'])]
    columns = [('scenarios', len(rows)), ('failed', len(rows) - len(ran)),
               ('crashes', sum(row['crashed'] for row in ran)),
               ('mean laps', '%.3f' % np.mean(laps) if laps else '-'),
               ('mean lap time (s)', '%.2f' % np.mean(lap_times) if lap_times else '-'),
               ('summed wall (s)', '%.1f' % sum(row['wall_seconds'] for row in ran))]
    widths = [max(len(name), len(str(value))) for name, value in columns]
    return '\n'.join('  '.join(str(cell).rjust(width) for cell, width in zip(line, widths))
                     for line in ([name for name, _ in columns], [value for _, value in columns]))


def varied_fields(rows):
    """The scenario fields that take more than one value in the rows."""
    return [field for field in SCENARIO_FIELDS if len({row[field] for row in rows}) > 1]


def plot(rows, path):
    """Laps against each varied field (one panel each; the scenario's index when none varies), crashes
    as red crosses; failed scenarios left out. Matplotlib's Figure draws on its Agg canvas: no display,
    and pyplot's global backend is left alone."""
    from matplotlib.figure import Figure
    ran = [row for row in rows if not row['error']]
    varied = varied_fields(ran)
    # A random sweep's env seeds are names, not a scale: their panel only when nothing else varies.
    fields = [field for field in varied if field != 'seed'] or varied or [INDEX_FIELD]
    columns = min(3, len(fields))
    line_count = math.ceil(len(fields) / columns)
    figure = Figure(figsize=(4.2 * columns, 3.4 * line_count), layout='constrained')
    axes = figure.subplots(line_count, columns, squeeze=False).ravel()
    for ax, field in zip(axes, fields):
        values = [row[field] for row in ran]
        if values and isinstance(values[0], str):  # a track: categories along x
            names = sorted(set(values))
            ax.set_xticks(range(len(names)), [os.path.basename(n) for n in names], rotation=20)
            values = [names.index(v) for v in values]
        for crashed, style in ((False, dict(marker='o', color='tab:blue', label='no crash')),
                               (True, dict(marker='x', color='tab:red', label='crashed'))):
            points = [(x, row['laps']) for x, row in zip(values, ran) if row['crashed'] == crashed]
            if points:
                ax.scatter(*zip(*points), s=22, **style)
        ax.set_xlabel(field)
        ax.set_ylabel('laps')
        ax.grid(alpha=0.3)
    if ran:
        axes[0].legend(loc='best', fontsize='small')
    for ax in axes[len(fields):]:
        ax.set_visible(False)
    failed = len(rows) - len(ran)
    figure.suptitle('%d scenario%s%s' % (len(rows), '' if len(rows) == 1 else 's',
                                         ', %d failed (not shown)' % failed if failed else ''))
    figure.savefig(path, dpi=100)
