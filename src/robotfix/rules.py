"""Every rule RobotFix can report. Codes are permanent: add, deprecate, never renumber.

Families (SPEC §4): RF0xx input, RF1xx refinements, RF2xx units and frames,
RF3xx initialisation, RF4xx base types, RF5xx annotations and interface files,
RF6xx launch files and the ROS graph, RF9xx analysis limits.
"""

from __future__ import annotations

from robotfix.diagnostics import Rule, Severity

W = Severity.WARNING

PYTHON_SYNTAX_ERROR = Rule("RF001", "python-syntax-error", "File is not valid Python 3")
PYTHON2_SOURCE = Rule(
    "RF002", "python2-source", "File is Python 2 and was not checked", W
)
UNREADABLE_FILE = Rule("RF003", "unreadable-file", "File cannot be read or decoded")
PATH_NOT_CHECKED = Rule(
    "RF004", "path-not-checked", "A file or folder was left out of the run", W
)
NEWER_PYTHON_SOURCE = Rule(
    "RF005",
    "newer-python-source",
    "File uses syntax newer than the Python running RobotFix and was not checked",
    W,
)
UNUSED_SUPPRESSION = Rule(
    "RF010", "unused-suppression", "A robotfix: ignore comment silences nothing", W
)

REFINEMENT_VIOLATED = Rule(
    "RF101", "refinement-violated", "Value violates its refinement on every execution"
)
REFINEMENT_UNPROVEN = Rule(
    "RF102", "refinement-unproven", "Refinement cannot be proved for every value", W
)

UNIT_MISMATCH = Rule(
    "RF201", "unit-mismatch", "Value has a different unit or frame than its target"
)
OPERAND_UNIT_MISMATCH = Rule(
    "RF202", "operand-unit-mismatch", "Operands of +, - or a comparison differ in unit"
)
IMPLICIT_UNIT_CHANGE = Rule(
    "RF203",
    "implicit-unit-change",
    "Value changes its unit by a time step or gain the code does not name",
    W,
)
TRANSFORM_FRAME_MISMATCH = Rule(
    "RF204",
    "transform-frame-mismatch",
    "A tf2 transform is applied to data in another frame, or given a frame it refuses",
)

USED_BEFORE_ASSIGNMENT = Rule(
    "RF301", "used-before-assignment", "Variable read before it is assigned"
)
UNSET_FIELD_DEFAULT = Rule(
    "RF302",
    "unset-field-default",
    "Message field never set, and its ROS default breaks its refinement",
)

BASE_TYPE_MISMATCH = Rule(
    "RF401", "base-type-mismatch", "Value does not fit the annotated base type"
)

ANNOTATION_SYNTAX = Rule("RF501", "annotation-syntax", "Annotation does not parse")
UNKNOWN_UNIT = Rule("RF502", "unknown-unit", "Unit name is a typo of a known unit")
UNKNOWN_NAME = Rule("RF503", "unknown-name", "Annotation names something not in scope")
UNKNOWN_MESSAGE_TYPE = Rule(
    "RF504", "unknown-message-type", "Interface file names an unknown message type"
)
UNKNOWN_FIELD = Rule(
    "RF505", "unknown-field", "Annotation names a field the message lacks"
)
MALFORMED_INTERFACE = Rule(
    "RF506", "malformed-interface-file", "Interface file line does not parse"
)
MISPLACED_UNIT = Rule(
    "RF507", "misplaced-unit", "Unit(), Frame() or Tag() used where it has no meaning"
)

DUPLICATE_INTERFACE = Rule(
    "RF510",
    "duplicate-interface-definition",
    "Two interface files define the same message type",
    W,
)

UNKNOWN_MESSAGE_CLASS = Rule(
    "RF508",
    "unknown-message-class",
    "Code uses a message type whose definition was not found",
    Severity.NOTE,
)
CONTRADICTORY_REFINEMENT = Rule(
    "RF509", "contradictory-refinement", "Refinement that no value can satisfy"
)

UNUSED_METADATA = Rule(
    "RF511",
    "unused-annotated-metadata",
    "Annotated metadata RobotFix cannot use (not a string)",
    Severity.NOTE,
)
MALFORMED_STUB = Rule(
    "RF512", "malformed-stub", "Stub file or stub annotation that does not read"
)

LAUNCH_PARAMETER_UNDECLARED = Rule(
    "RF601",
    "launch-parameter-undeclared",
    "A launch file sets a parameter its node does not declare",
    W,
)
PARAMETER_SECTION_UNMATCHED = Rule(
    "RF602",
    "parameter-section-unmatched",
    "A parameter file's section names no node RobotFix read in the workspace or "
    "its launch files",
    Severity.NOTE,
)
TOPIC_TYPE_MISMATCH = Rule(
    "RF603",
    "topic-type-mismatch",
    "Two nodes use one topic, service or action name with different interface types",
)
QOS_INCOMPATIBLE = Rule(
    "RF604",
    "qos-incompatible",
    "A subscription's QoS can never match a publisher's on its topic",
)
QOS_MAYBE_INCOMPATIBLE = Rule(
    "RF605",
    "qos-maybe-incompatible",
    "A subscription's QoS may not match a publisher's (a profile that can change)",
    W,
)
TOPIC_NOT_PUBLISHED = Rule(
    "RF606",
    "topic-not-published",
    "A topic is subscribed but published nowhere in the checked workspace",
    Severity.NOTE,
)
TOPIC_NOT_SUBSCRIBED = Rule(
    "RF607",
    "topic-not-subscribed",
    "A topic is published but subscribed nowhere in the checked workspace",
    Severity.NOTE,
)

SOLVER_UNKNOWN = Rule("RF901", "solver-unknown", "Solver could not decide", W)
ANALYSIS_BUDGET = Rule(
    "RF902", "analysis-budget-exceeded", "Analysis stopped early for this file", W
)

ALL_RULES: dict[str, Rule] = {
    r.code: r
    for r in (
        PYTHON_SYNTAX_ERROR,
        PYTHON2_SOURCE,
        UNREADABLE_FILE,
        PATH_NOT_CHECKED,
        NEWER_PYTHON_SOURCE,
        UNUSED_SUPPRESSION,
        REFINEMENT_VIOLATED,
        REFINEMENT_UNPROVEN,
        UNIT_MISMATCH,
        OPERAND_UNIT_MISMATCH,
        IMPLICIT_UNIT_CHANGE,
        TRANSFORM_FRAME_MISMATCH,
        USED_BEFORE_ASSIGNMENT,
        UNSET_FIELD_DEFAULT,
        BASE_TYPE_MISMATCH,
        ANNOTATION_SYNTAX,
        UNKNOWN_UNIT,
        UNKNOWN_NAME,
        UNKNOWN_MESSAGE_TYPE,
        UNKNOWN_FIELD,
        MALFORMED_INTERFACE,
        MISPLACED_UNIT,
        UNKNOWN_MESSAGE_CLASS,
        CONTRADICTORY_REFINEMENT,
        UNUSED_METADATA,
        MALFORMED_STUB,
        DUPLICATE_INTERFACE,
        LAUNCH_PARAMETER_UNDECLARED,
        PARAMETER_SECTION_UNMATCHED,
        TOPIC_TYPE_MISMATCH,
        QOS_INCOMPATIBLE,
        QOS_MAYBE_INCOMPATIBLE,
        TOPIC_NOT_PUBLISHED,
        TOPIC_NOT_SUBSCRIBED,
        SOLVER_UNKNOWN,
        ANALYSIS_BUDGET,
    )
}
RULES_BY_NAME: dict[str, Rule] = {r.name: r for r in ALL_RULES.values()}
# reported by a run's graph check (`graphcheck.py`), after each file's own check:
# a file's check leaves their suppressions to it (no RF010)
GRAPH_RULES = frozenset(
    {
        name
        for r in (
            TOPIC_TYPE_MISMATCH,
            QOS_INCOMPATIBLE,
            QOS_MAYBE_INCOMPATIBLE,
            TOPIC_NOT_PUBLISHED,
            TOPIC_NOT_SUBSCRIBED,
        )
        for name in (r.code, r.name)
    }
)
# reported on a Python launch file's lines by the run's launch check
# (`launchcheck.py`: its values, its parameters, a file it cannot read), after the
# file's own check: in a launch file, that check leaves their suppressions to it
LAUNCH_RULES = frozenset(
    {
        name
        for r in (
            PATH_NOT_CHECKED,
            REFINEMENT_VIOLATED,
            REFINEMENT_UNPROVEN,
            BASE_TYPE_MISMATCH,
            LAUNCH_PARAMETER_UNDECLARED,
            PARAMETER_SECTION_UNMATCHED,
        )
        for name in (r.code, r.name)
    }
)
