"""The static ROS graph of a checked workspace (issue 23, section 2): nodes from
code and launch files, their endpoints (publishers, subscriptions, services,
clients, action servers and clients, parameters C++ declares) with names resolved
as ROS resolves them, message types and ROS 2 QoS profiles where they are constants.

`model.py` the data (and its JSON form, kept in the result cache), `names.py` ROS
name resolution, `qos.py` QoS profiles and their compatibility, `python.py` the
endpoints of a Python file (`ast`), `cpp.py` those of a C++ file (tree-sitter, the
only import of it), `build.py` the graph of a run. Nothing is run.
"""
