"""Turn one pytest-benchmark run into the tables of benchmarks/README.md.

    python -m pytest benchmarks --benchmark-only --benchmark-json=bench.json
    python tools/bench_table.py bench.json            # prints the Markdown
    python tools/bench_table.py bench.json --write    # replaces the table in benchmarks/README.md

Medians only, all from the one run given, and ratios between engines measured in that run:
absolute times depend on the machine, ratios are the claim.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

README = Path(__file__).resolve().parent.parent / "benchmarks" / "README.md"
START, END = "<!-- bench-table -->", "<!-- /bench-table -->"

# (benchmark name, what it measures, target from issue 4 if any)
ROWS = [
    ("test_solve_article_case[figure8]", "Figure 8 (90 robots), auto engine", ""),
    ("test_solve_article_case[case1]", "Case 1 (30 robots), auto engine", ""),
    ("test_solve_article_case[case2]", "Case 2 (110 robots), auto engine", ""),
    ("test_solve_article_case[case3]", "Case 3 (872 robots), auto engine", "< 1 ms"),
    ("test_solve_case3_in_process[structure]", "Case 3, structure engine", "< 1 ms"),
    ("test_solve_case3_in_process[fast]", "Case 3, fast (numpy) enumeration + partition", "< 1 ms"),
    ("test_solve_case3_in_process[csp]", "Case 3, python-constraint enumeration + partition", ""),
    (
        "test_solve_case3_whole_process",
        "`teleop-ui solve rules/teams/case3.yaml`, whole process",
        "< 0.3 s",
    ),
    ("test_start_bare_interpreter", "a bare interpreter, whole process (peer)", ""),
    (
        "test_start_solve_case3",
        "`python -m solver solve rules/teams/case3.yaml`, whole process",
        "",
    ),
    ("test_read_team_of_100_types[1e3 counts]", "read a team: 100 types, 1..1,000 counts", ""),
    ("test_read_team_of_100_types[1e5 counts]", "read a team: 100 types, 1..100,000 counts", ""),
    (
        "test_parse_team_file_with_libyaml",
        "the same team file parsed by yaml.CSafeLoader (peer)",
        "",
    ),
    ("test_refuse_a_deep_nest[flow-1 KB]", "refuse `[` x 1,000 (nested past 64)", ""),
    ("test_refuse_a_deep_nest[flow-16 MB]", "refuse `[` x 16,000,000 (nested past 64)", ""),
    ("test_refuse_a_deep_nest[block-1 KB]", "refuse `- ` x 500 (nested past 64)", ""),
    ("test_refuse_a_deep_nest[block-16 MB]", "refuse `- ` x 8,000,000 (nested past 64)", ""),
    ("test_count_scaled_team[1e5]", "count 10^5 robots (1 type)", ""),
    ("test_count_scaled_team[1e7]", "count 10^7 robots (10 types, 1 constraint)", ""),
    ("test_count_scaled_team[1e9]", "count 10^9 robots (10 types, 1 constraint)", ""),
    ("test_count_scaled_team[1e12]", "count 10^12 robots (100 types, 1 constraint)", "< 10 ms"),
    ("test_count_10_to_the_30_exactly", "count 10^30 robots (30 characteristics)", ""),
    ("test_enumerate_1e6_fast", "enumerate + partition 999,000 robots, fast engine", ""),
    ("test_enumerate_1e6_csp", "enumerate + partition 999,000 robots, csp engine (1 round)", ""),
    (
        "test_iterate_1e6_python_constraint",
        "python-constraint2 solution iterator alone, 999,000 robots (1 round)",
        "",
    ),
    ("test_list_robots_as_csv", "`robots` as CSV: solve + list 199,000 robots", ""),
    ("test_list_robots_as_jsonl", "`robots` as JSON lines: solve + list 199,000 robots", ""),
    (
        "test_list_robots_as_csv_python_constraint_peer",
        "python-constraint2 iterator + dict + csv.writer, the same 199,000 robots (1 round)",
        "",
    ),
    (
        "test_robots_command_lists_3_6_million_robots",
        "`robots` command in-process (terminal-safe output): 3,610,000 robots",
        "",
    ),
    (
        "test_robots_numpy_listing_peer",
        "numpy listing written for that team alone, the same bytes (peer)",
        "",
    ),
    (
        "test_first_1000_robots[2 x 40 values]",
        "`robots`, first 1,000 lines: 1,600 robots, each its own configuration",
        "",
    ),
    (
        "test_first_1000_robots[2 x 640 values]",
        "`robots`, first 1,000 lines: 409,600 robots, each its own configuration",
        "< 1 s",
    ),
    (
        "test_first_1000_robots[3 x 400 values]",
        "`robots`, first 1,000 lines: 64,000,000 robots, each its own configuration",
        "< 1 s",
    ),
    (
        "test_first_1000_robots[3 x 80 values in windows]",
        "`robots`, first 1,000 lines: 512,000 robots whose values overlap (8,000 configurations)",
        "< 1 s",
    ),
    (
        "test_first_1000_robots[2 x 640 values, linked]",
        "`robots`, first 1,000 lines: 409,599 robots, two characteristics linked by a rule",
        "< 1 s",
    ),
    (
        "test_enumeration_memory_does_not_grow_with_robots",
        "enumerate + partition 9,990,000 robots, fast engine (1 round)",
        "",
    ),
    (
        "test_check_large_rule_set",
        "`check`: 50 types, 100 sensor types, 200 constraints",
        "seconds",
    ),
    ("test_check_doubled_rule_sets[x1]", "`check`: the same, scale x1 (for the growth ratios)", ""),
    (
        "test_check_doubled_rule_sets[x2]",
        "`check`: 100 types, 200 sensor types, 400 constraints",
        "",
    ),
    (
        "test_check_doubled_rule_sets[x4]",
        "`check`: 200 types, 400 sensor types, 800 constraints",
        "",
    ),
    ("test_count_overlapping_windows[20]", "count: 3 x 20 values, each in two windows", ""),
    ("test_count_overlapping_windows[40]", "count: 3 x 40 values, each in two windows", ""),
    ("test_count_overlapping_windows[80]", "count: 3 x 80 values, each in two windows", ""),
    ("test_count_overlapping_windows[160]", "count: 3 x 160 values, each in two windows", ""),
    (
        "test_solve_overlapping_windows[20]",
        "solve: 3 x 20 values in windows (125 configurations)",
        "",
    ),
    (
        "test_solve_overlapping_windows[40]",
        "solve: 3 x 40 values in windows (1,000 configurations)",
        "",
    ),
    (
        "test_solve_overlapping_windows[80]",
        "solve: 3 x 80 values in windows (8,000 configurations)",
        "< 2 s",
    ),
    ("test_radar_chart_of_case3_as_png", "radar chart of Case 3 as PNG", ""),
    ("test_batch_solves_40_teams_in_one_process", "`batch` of 40 teams, one process", ""),
    (
        "test_batch_rerun_of_40_unchanged_teams_solves_nothing",
        "`batch` rerun of 40 unchanged teams",
        "",
    ),
    (
        "test_count_growth_in_values[5120]",
        "read + count: 5,120 values in 1,280 components, listed whole",
        "",
    ),
    (
        "test_count_growth_in_values[10240]",
        "read + count: 10,240 values in 2,560 components, listed whole",
        "",
    ),
    (
        "test_count_growth_in_values[20480]",
        "read + count: 20,480 values in 5,120 components, listed whole",
        "",
    ),
    (
        "test_check_growth_in_values[5120]",
        "read + `check`: 5,120 values in 1,280 components, listed whole",
        "",
    ),
    (
        "test_check_growth_in_values[10240]",
        "read + `check`: 10,240 values in 2,560 components, listed whole",
        "",
    ),
    (
        "test_check_growth_in_values[20480]",
        "read + `check`: 20,480 values in 5,120 components, listed whole",
        "",
    ),
    (
        "test_case3_read_and_solved_in_process",
        "Case 3 read + solved in-process, `solve(load_team(...))` (CPU)",
        "",
    ),
    (
        "test_case3_read_and_solved_in_process_rules_read_anew",
        "Case 3 read + solved in-process, the rule set read anew each time (CPU)",
        "",
    ),
    (
        "test_case3_python_constraint_peer_in_process",
        "Case 3, PyYAML + python-constraint2 written directly (peer, CPU)",
        "",
    ),
    ("test_whole_process_cpu[bare interpreter]", "a bare interpreter, whole process (CPU)", ""),
    (
        "test_whole_process_cpu[imports only: PyYAML, dataclasses]",
        "an interpreter importing only PyYAML and dataclasses (floor, CPU)",
        "",
    ),
    (
        "test_whole_process_cpu[imports only: PyYAML, dataclasses, lxml]",
        "an interpreter importing only PyYAML, dataclasses and lxml (floor, CPU)",
        "",
    ),
    ("test_whole_process_cpu[solve case3]", "`teleop-ui solve case3`, whole process (CPU)", ""),
    ("test_whole_process_cpu[peer script]", "tools/peer_case3.py, whole process (CPU)", ""),
    (
        "test_whole_process_cpu[identify a URDF]",
        "`teleop-ui identify` of a URDF, whole process (CPU)",
        "",
    ),
    (
        "test_batch_worker_solves_50_teams",
        "`batch` worker's work for 50 copies of Case 3 (CPU)",
        "",
    ),
    (
        "test_plain_loop_over_the_api_solves_50_teams",
        "plain loop over the Python API writing compact JSON, the same 50 teams (peer, CPU)",
        "",
    ),
    (
        "test_check_non_transitive_of_1000_sliding_arrangements",
        "`check`: 1000 overlapping arrangements (non-transitive witnesses)",
        "",
    ),
    (
        "test_radar_chart_of_a_count_spoke_of_100000_values_as_png",
        "radar chart with a 100,000-value count spoke as PNG",
        "",
    ),
    (
        "test_placing_the_topic_graph[20 robots x 100 topics]",
        "`watch` poll: topics of 20 robots x 100 placed on their robots",
        "",
    ),
    (
        "test_placing_the_topic_graph[200 robots x 100 topics]",
        "`watch` poll: topics of 200 robots x 100 placed on their robots",
        "",
    ),
]

# The studio: a change of selection over HTTP, per change (bench_studio.py's extra_info: its
# timed run is all the changes at once), beside its in-process peer in the same run.
STUDIO = [
    ("test_studio_answers_a_change_of_case_3", "totals, Case 3", "<= 100 ms"),
    ("test_studio_answers_a_change_of_ten_million_robots", "totals, 9,990,000 robots", "<= 100 ms"),
    (
        "test_studio_answers_a_change_of_case_3_with_its_radar_chart",
        "totals then radar chart, Case 3",
        "<= 100 ms",
    ),
    (
        "test_studio_answers_a_change_of_ten_million_robots_with_its_radar_chart",
        "totals then radar chart, 9,990,000 robots",
        "<= 100 ms",
    ),
    *(
        (
            f"test_studio_draws_the_charts_pages_other_charts_of_a_new_selection[{kind}-{team}]",
            f"{kind} chart, {label}",
            "",
        )
        for kind in ("bars", "matrix")
        for team, label in (("case3", "Case 3"), ("1e7", "9,990,000 robots"))
    ),
]

# `watch` latency: change on a real roscore -> event (recorded by bench_watch.py in extra_info).
WATCH = [
    (
        "test_switching_the_active_robot[10 robots]",
        "active robot switched (10 robots)",
        "<= 0.2 s interval + 50 ms",
    ),
    (
        "test_bare_param_update_push_peer[10 robots]",
        "peer: the master's bare paramUpdate push (10 robots)",
        "",
    ),
    (
        "test_switching_the_active_robot[500 robots]",
        "active robot switched (500 robots)",
        "95th percentile <= 100 ms",
    ),
    (
        "test_bare_param_update_push_peer[500 robots]",
        "peer: the master's bare paramUpdate push (500 robots)",
        "",
    ),
    ("test_registering_a_robots_topics", "a robot's topics registered", ""),
    ("test_setting_a_new_robots_description", "a new robot's description set", ""),
    (
        "test_active_robot_message_to_published_configuration[10 robots]",
        "ROS 2: active robot message -> configuration received (10 robots)",
        "<= 50 ms",
    ),
    (
        "test_bare_dds_echo_round_trip_peer[10 robots]",
        "ROS 2 peer: bare DDS echo round trip, same QoS (10 robots)",
        "",
    ),
    (
        "test_new_robots_description_to_its_first_event[10 robots]",
        "ROS 2: a new robot's description -> robot_added (10 robots)",
        "",
    ),
    (
        "test_active_robot_message_to_published_configuration[100 robots]",
        "ROS 2: active robot message -> configuration received (100 robots)",
        "",
    ),
    (
        "test_bare_dds_echo_round_trip_peer[100 robots]",
        "ROS 2 peer: bare DDS echo round trip, same QoS (100 robots)",
        "",
    ),
    (
        "test_new_robots_description_to_its_first_event[100 robots]",
        "ROS 2: a new robot's description -> robot_added (100 robots)",
        "",
    ),
    (
        "test_active_robot_message_to_published_configuration[10 robots, layouts]",
        "ROS 2 --layouts: active robot -> configuration and layouts (10 robots)",
        "",
    ),
    (
        "test_active_robot_message_to_served_event[10 robots, layouts]",
        "ROS 2 --layouts: active robot -> served event stream (10 robots)",
        "",
    ),
    (
        "test_bare_dds_echo_round_trip_peer[10 robots, layouts]",
        "ROS 2 --layouts peer: bare DDS echo round trip (10 robots)",
        "",
    ),
    (
        "test_new_robots_description_to_its_first_event[10 robots, layouts]",
        "ROS 2 --layouts: new description -> robot_added, layouts (10 robots)",
        "",
    ),
    (
        "test_active_robot_message_to_published_configuration[100 robots, layouts]",
        "ROS 2 --layouts: active robot -> configuration and layouts (100 robots)",
        "",
    ),
    (
        "test_active_robot_message_to_served_event[100 robots, layouts]",
        "ROS 2 --layouts: active robot -> served event stream (100 robots)",
        "",
    ),
    (
        "test_bare_dds_echo_round_trip_peer[100 robots, layouts]",
        "ROS 2 --layouts peer: bare DDS echo round trip (100 robots)",
        "",
    ),
    (
        "test_new_robots_description_to_its_first_event[100 robots, layouts]",
        "ROS 2 --layouts: new description -> robot_added, layouts (100 robots)",
        "",
    ),
    ("test_setting_a_large_description[parsed]", "a 1.5 MB description set, parsed", ""),
    (
        "test_setting_a_large_description[cached]",
        "a 1.5 MB description set, identification cached",
        "",
    ),
]

# (label, slower benchmark, faster benchmark, target)
RATIOS = [
    (
        "3.6 M robots: numpy listing (peer) / `robots` command, byte-identical",
        "test_robots_numpy_listing_peer",
        "test_robots_command_lists_3_6_million_robots",
        ">= 1.0",
    ),
    (
        "Case 3: csp engine / structure engine",
        "test_solve_case3_in_process[csp]",
        "test_solve_case3_in_process[structure]",
        "",
    ),
    (
        "Case 3: csp engine / fast engine",
        "test_solve_case3_in_process[csp]",
        "test_solve_case3_in_process[fast]",
        "",
    ),
    (
        "10^6 robots: python-constraint2 iterator alone / fast enumeration + partition",
        "test_iterate_1e6_python_constraint",
        "test_enumerate_1e6_fast",
        ">= 200",
    ),
    (
        "`robots` CSV, 199,000 robots: python-constraint2 + dict + csv / `robots`",
        "test_list_robots_as_csv_python_constraint_peer",
        "test_list_robots_as_csv",
        ">= 10",
    ),
    (
        "10^6 robots: csp enumeration + partition / fast enumeration + partition",
        "test_enumerate_1e6_csp",
        "test_enumerate_1e6_fast",
        "",
    ),
    (
        "`robots`, first 1,000 lines: 409,600 robots / 1,600 robots",
        "test_first_1000_robots[2 x 640 values]",
        "test_first_1000_robots[2 x 40 values]",
        "",
    ),
    (
        "`robots`, first 1,000 lines: 64,000,000 robots / 1,600 robots",
        "test_first_1000_robots[3 x 400 values]",
        "test_first_1000_robots[2 x 40 values]",
        "",
    ),
    (
        "`robots`, first 1,000 lines: 409,599 linked robots / 1,600 robots",
        "test_first_1000_robots[2 x 640 values, linked]",
        "test_first_1000_robots[2 x 40 values]",
        "",
    ),
    (
        "start-up: `solve case3` whole process / bare interpreter",
        "test_start_solve_case3",
        "test_start_bare_interpreter",
        "<= 4",
    ),
    (
        "read a team: 100,000 counts / 1,000 counts (proportional to the file: 1)",
        "test_read_team_of_100_types[1e5 counts]",
        "test_read_team_of_100_types[1e3 counts]",
        "",
    ),
    (
        "refuse a flow nest: 16 MB / 1 KB (in proportion to the bytes: 16,000)",
        "test_refuse_a_deep_nest[flow-16 MB]",
        "test_refuse_a_deep_nest[flow-1 KB]",
        "",
    ),
    (
        "refuse a block nest: 16 MB / 1 KB (in proportion to the bytes: 16,000)",
        "test_refuse_a_deep_nest[block-16 MB]",
        "test_refuse_a_deep_nest[block-1 KB]",
        "",
    ),
    (
        "`check` growth, first doubling (x2 / x1; linear: 2)",
        "test_check_doubled_rule_sets[x2]",
        "test_check_doubled_rule_sets[x1]",
        "<= 2.5",
    ),
    (
        "`check` growth, second doubling (x4 / x2; linear: 2)",
        "test_check_doubled_rule_sets[x4]",
        "test_check_doubled_rule_sets[x2]",
        "<= 2.5",
    ),
    (
        "overlapping windows, count: 40 / 20 values per characteristic",
        "test_count_overlapping_windows[40]",
        "test_count_overlapping_windows[20]",
        "<= 2.5",
    ),
    (
        "overlapping windows, count: 80 / 40 values per characteristic",
        "test_count_overlapping_windows[80]",
        "test_count_overlapping_windows[40]",
        "<= 2.5",
    ),
    (
        "overlapping windows, count: 160 / 80 values per characteristic",
        "test_count_overlapping_windows[160]",
        "test_count_overlapping_windows[80]",
        "<= 2.5",
    ),
    (
        "overlapping windows, solve: 80 / 40 values (8x the configurations listed)",
        "test_solve_overlapping_windows[80]",
        "test_solve_overlapping_windows[40]",
        "<= 20 (8 x 2.5)",
    ),
    (
        "read + count growth: 10,240 / 5,120 values (linear: 2)",
        "test_count_growth_in_values[10240]",
        "test_count_growth_in_values[5120]",
        "<= 2.5",
    ),
    (
        "read + count growth: 20,480 / 10,240 values (linear: 2)",
        "test_count_growth_in_values[20480]",
        "test_count_growth_in_values[10240]",
        "<= 2.5",
    ),
    (
        "read + `check` growth: 10,240 / 5,120 values (linear: 2)",
        "test_check_growth_in_values[10240]",
        "test_check_growth_in_values[5120]",
        "<= 2.5",
    ),
    (
        "read + `check` growth: 20,480 / 10,240 values (linear: 2)",
        "test_check_growth_in_values[20480]",
        "test_check_growth_in_values[10240]",
        "<= 2.5",
    ),
    (
        "Case 3 in-process: python-constraint2 peer / `solve(load_team(...))`",
        "test_case3_python_constraint_peer_in_process",
        "test_case3_read_and_solved_in_process",
        ">= 3",
    ),
    (
        "Case 3 in-process: python-constraint2 peer / the same, rule set read anew",
        "test_case3_python_constraint_peer_in_process",
        "test_case3_read_and_solved_in_process_rules_read_anew",
        "",
    ),
    (
        "CPU: `solve case3` whole process / bare interpreter",
        "test_whole_process_cpu[solve case3]",
        "test_whole_process_cpu[bare interpreter]",
        "<= 3",
    ),
    (
        "CPU: `identify` whole process / bare interpreter",
        "test_whole_process_cpu[identify a URDF]",
        "test_whole_process_cpu[bare interpreter]",
        "<= 3",
    ),
    (
        "CPU: importing PyYAML and dataclasses only / bare interpreter (the floor of `solve`)",
        "test_whole_process_cpu[imports only: PyYAML, dataclasses]",
        "test_whole_process_cpu[bare interpreter]",
        "",
    ),
    (
        "CPU: importing PyYAML, dataclasses and lxml only / bare interpreter (`identify`'s)",
        "test_whole_process_cpu[imports only: PyYAML, dataclasses, lxml]",
        "test_whole_process_cpu[bare interpreter]",
        "",
    ),
    (
        "CPU: `solve case3` whole process / its floor (PyYAML and dataclasses imported)",
        "test_whole_process_cpu[solve case3]",
        "test_whole_process_cpu[imports only: PyYAML, dataclasses]",
        "",
    ),
    (
        "CPU: `identify` whole process / its floor (PyYAML, dataclasses, lxml imported)",
        "test_whole_process_cpu[identify a URDF]",
        "test_whole_process_cpu[imports only: PyYAML, dataclasses, lxml]",
        "",
    ),
    (
        "CPU: peer script whole process / bare interpreter",
        "test_whole_process_cpu[peer script]",
        "test_whole_process_cpu[bare interpreter]",
        "",
    ),
    (
        "CPU: compact-JSON loop over the API / `batch` worker, 50 teams",
        "test_plain_loop_over_the_api_solves_50_teams",
        "test_batch_worker_solves_50_teams",
        ">= 1.0",
    ),
    (
        "ROS 2 `watch`, 10 robots: active robot -> configuration / bare DDS echo round trip",
        "test_active_robot_message_to_published_configuration[10 robots]",
        "test_bare_dds_echo_round_trip_peer[10 robots]",
        "",
    ),
    (
        "ROS 2 `watch`, 100 robots: active robot -> configuration / bare DDS echo round trip",
        "test_active_robot_message_to_published_configuration[100 robots]",
        "test_bare_dds_echo_round_trip_peer[100 robots]",
        "<= 3",
    ),
    (
        "ROS 2 `watch --layouts --serve`, 10 robots: active robot -> configuration with its "
        "layouts / bare DDS echo round trip",
        "test_active_robot_message_to_published_configuration[10 robots, layouts]",
        "test_bare_dds_echo_round_trip_peer[10 robots, layouts]",
        "<= 2",
    ),
    (
        "ROS 2 `watch --layouts --serve`, 100 robots: active robot -> configuration with its "
        "layouts / bare DDS echo round trip",
        "test_active_robot_message_to_published_configuration[100 robots, layouts]",
        "test_bare_dds_echo_round_trip_peer[100 robots, layouts]",
        "<= 2",
    ),
    (
        "`watch` topic placement: 200 robots / 20 robots (linear: about 10)",
        "test_placing_the_topic_graph[200 robots x 100 topics]",
        "test_placing_the_topic_graph[20 robots x 100 topics]",
        "",
    ),
]

# (label, slower, faster, target): ratios of the 95th percentiles the live benchmarks record.
P95_RATIOS = [
    (
        "ROS 1 `watch`, 10 robots: switch / bare paramUpdate push (95th percentiles)",
        "test_switching_the_active_robot[10 robots]",
        "test_bare_param_update_push_peer[10 robots]",
        "",
    ),
    (
        "ROS 1 `watch`, 500 robots: switch / bare paramUpdate push (95th percentiles)",
        "test_switching_the_active_robot[500 robots]",
        "test_bare_param_update_push_peer[500 robots]",
        "",
    ),
]


def seconds(value: float) -> str:
    if value >= 1:
        return f"{value:.2f} s"
    if value >= 1e-3:
        return f"{value * 1e3:.2f} ms"
    return f"{value * 1e6:.0f} µs"


def table(run: dict[str, Any]) -> str:
    medians = {b["name"]: b["stats"]["median"] for b in run["benchmarks"]}
    rounds = {b["name"]: b["stats"]["rounds"] for b in run["benchmarks"]}
    machine = run.get("machine_info", {})
    cpu = machine.get("cpu", {})
    lines = [
        f"One run, {run.get('datetime', '')[:10]}, on {cpu.get('brand_raw', 'this machine')} "
        f"({cpu.get('count', '?')} cores), Python {machine.get('python_version', '?')}. "
        "Medians; `rounds` is how many timed runs.",
        "",
        "| benchmark | median | rounds | target |",
        "|---|---:|---:|---|",
    ]
    for name, label, target in ROWS:
        if name in medians:
            lines.append(f"| {label} | {seconds(medians[name])} | {rounds[name]} | {target} |")
    extra = {b["name"]: b.get("extra_info", {}) for b in run["benchmarks"]}
    watched = [
        (label, extra[name], target)
        for name, label, target in WATCH
        if "median_ms" in extra.get(name, {})
    ]
    if watched:
        lines += [
            "",
            "| `watch`: change on the master or DDS graph -> event | changes | median | 95th "
            "percentile | target |",
            "|---|---:|---:|---:|---|",
        ]
        lines += [
            f"| {label} | {info['changes']} | {info['median_ms']} ms | {info['p95_ms']} ms "
            f"| {target} |"
            for label, info, target in watched
        ]
    studio = [
        (label, extra[name], target)
        for name, label, target in STUDIO
        if "median_ms" in extra.get(name, {})
    ]
    if studio:
        lines += [
            "",
            "| `studio`: a change of selection over HTTP | changes | median | 95th percentile "
            "| in-process peer, median | target |",
            "|---|---:|---:|---:|---:|---|",
        ]
        lines += [
            f"| {label} | {info['changes']} | {info['median_ms']} ms | {info['p95_ms']} ms "
            f"| {info.get('peer_median_ms', '')} ms | {target} |"
            for label, info, target in studio
        ]
    lines += ["", "| ratio (same run) | value | target |", "|---|---:|---|"]
    for label, slow, fast, target in RATIOS:
        if slow in medians and fast in medians:
            lines.append(f"| {label} | {medians[slow] / medians[fast]:.1f}x | {target} |")
    for label, slow, fast, target in P95_RATIOS:
        if "p95_ms" in extra.get(slow, {}) and "p95_ms" in extra.get(fast, {}):
            ratio = extra[slow]["p95_ms"] / extra[fast]["p95_ms"]
            lines.append(f"| {label} | {ratio:.1f}x | {target} |")
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("json", type=Path, help="pytest --benchmark-json output")
    parser.add_argument("--write", action="store_true", help="update benchmarks/README.md")
    args = parser.parse_args(argv)
    text = table(json.loads(args.json.read_text(encoding="utf-8")))
    if not args.write:
        sys.stdout.write(text)
        return 0
    readme = README.read_text(encoding="utf-8")
    head, rest = readme.split(START, 1)
    _, tail = rest.split(END, 1)
    README.write_text(f"{head}{START}\n{text}{END}{tail}", encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
