"""`rosservice call` for every service call of one test (the harness's RosSystem.service): rosservice's
own call_service, in one process kept for the test's master, where each `rosservice call` would start
a Python and import rospy again (0.9 s of CPU a call). One request a line on stdin, JSON
{"service": name, "request": YAML text as `rosservice call` takes it, "wait": true for `rosservice
call --wait`}; one answer a line on stdout, JSON {"response": the response as `rosservice call`
prints it} or {"error": what rosservice said}."""
import json
import sys

import rosgraph.names
import rospy
import rosservice
import yaml

for line in sys.stdin:
    query = json.loads(line)
    try:
        # as `rosservice call NAME ARG`: the name resolved as a script's, the argument read as YAML
        name = rosgraph.names.script_resolve_name('rosservice', query['service'])
        if query.get('wait'):
            rospy.wait_for_service(name)  # as `rosservice call --wait`; the harness's timeout stops it
        _, response = rosservice.call_service(name, [yaml.safe_load(query['request'] or "''")])
        answer = {'response': str(response)}
    except Exception as e:  # rosservice's ROSServiceException, a name without a service ...: the caller says
        answer = {'error': '%s: %s' % (type(e).__name__, e)}
    print(json.dumps(answer), flush=True)
