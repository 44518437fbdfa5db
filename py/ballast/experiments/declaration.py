"""What a study needs to know of an experiment, without YADE (:class:`Declaration`)."""


class Declaration:
    """An experiment as the study machinery sees it.

    name        the experiment's name (its folder under ballast/experiments/)
    owner       how its errors name it (its Parameters' OWNER, 'Oedometer'); default the name
    title       its heading in docs/parameters.md ('The oedometer (`Oedometer(...)`, ...)')
    bounds      [text]: the checks between its parameters, for docs/parameters.md
    params      {name: Param}: the parameters, each declared once (units, ranges, defaults)
    check       check(values, text=False) -> the checked parameters (text=True: cells of a table)
    script      the command line that runs one realization, relative to the repository
    sets        {'results': name, 'runId': name, 'sampleStore': name or None, 'resume': name (optional)}: the
                parameters the study sets for a run (where the run writes, its id, where prepared samples are
                stored, that it goes on with the killed run in its folder: given only then)
    sampleKey   sampleKey(p) -> the file name of the prepared sample the run p uses, or None: runs with the
                same name share one sample (the study builds it once)
    cost        cost(p) -> a number that orders runs by their cost: the cheapest of a group builds the sample
    recordTimes recordTimes(p) -> loading times [s] whose neighbouring rows of checks.csv a record keeps
    results     [(name, unit)]: the results of summary.json (or derived) a study tabulates, a column of
                runs.csv each
    statistics  [name]: the results whose mean and standard deviation per value stats.csv gives
    derived     derived(run) -> {name: value}: results a run's files give beyond summary.json
                (run: a ballast.study.data.Run), merged into its summary when a study is read
    response    (name, ...): the result the analyses test, in order of preference: the first one every
                run of a study has (runs of older versions may lack the later results)
    brief       brief(summary) -> the few words of a finished run's line in a study's progress (default: the
                first three results with their units)
    tested      {key: (result, words)}: results besides the response whose within-seed test a study's report
                (ballast.analysis.report) adds to test.json under key and names by words (default: none)
    recordFiles the files of a run its compact record keeps whole (ballast.study.records); None: the
                oedometer's (summary, row, psd and cycles whole, fd, checks and crushes thinned)
    """

    def __init__(self, name, params, check, script, sets, sampleKey=None, cost=None, recordTimes=None, results=(),
                 statistics=(), derived=None, response=(), owner=None, title=None, bounds=(), brief=None,
                 recordFiles=None, tested=None):
        self.name, self.params, self.check, self.script, self.sets = name, params, check, script, sets
        self.owner = owner or name
        self.title, self.bounds = title or name, list(bounds)
        self.sampleKey = sampleKey or (lambda p: None)
        self.cost = cost or (lambda p: 0.0)
        self.recordTimes = recordTimes or (lambda p: ())
        self.results, self.statistics, self.response = list(results), list(statistics), tuple(response)
        self.derived = derived or (lambda run: {})
        self.brief = brief or self._brief
        self.recordFiles = None if recordFiles is None else tuple(recordFiles)
        self.tested = dict(tested or {})

    def _brief(self, summary):
        return ', '.join('%s %s%s' % (name, _number(summary.get(name)), '' if unit == '-' else ' ' + unit)
                         for name, unit in self.results[:3])

    def studySets(self):
        """The parameter names a study sets itself (a table may not have them as columns)."""
        return tuple(v for v in self.sets.values() if v)

    def __repr__(self):
        return '<Declaration %s: %d parameters, script %s>' % (self.name, len(self.params), self.script)


def _number(v):
    return '%.4g' % v if isinstance(v, (int, float)) else '?'
