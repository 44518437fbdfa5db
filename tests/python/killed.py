"""A finished run's folder copied as a run that was killed (Experiment.resumeKilled's input), for the tests of
resume in every experiment."""
import json
import os
import shutil
import subprocess


def killedCopy(test, results, state):
    """The run `test` copied to results/<run id> as a run killed after it saved `state`: run.json 'running' with a
    process that is gone, no summary.json, no state-end."""
    folder = os.path.join(results, test.runId)
    shutil.copytree(test.out, folder)
    for name in ('summary.json', 'state-end.yade.gz'):
        os.remove(os.path.join(folder, name))
    gone = subprocess.Popen(['true'])
    gone.wait()
    with open(os.path.join(folder, 'run.json')) as fh:
        doc = json.load(fh)
    doc.update(status='running', lastState=state, pid=gone.pid)
    with open(os.path.join(folder, 'run.json'), 'w') as fh:
        json.dump(doc, fh)
    return folder
