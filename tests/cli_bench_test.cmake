# gridcar bench end to end on benchmarks/problems/smoke.yaml (every planner, embedded campus):
# .log -> ompl_benchmark_statistics database with every planner's runs -> report.md and plots;
# shards merged into one database and one report; bad problem files exit 2 naming the file.
include("${CMAKE_CURRENT_LIST_DIR}/cli_common.cmake")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(SMOKE "${SOURCE_DIR}/benchmarks/problems/smoke.yaml")

function(count_planners db expected)
  execute_process(COMMAND /usr/bin/python3 -c
    "import sqlite3,sys; c=sqlite3.connect(sys.argv[1]); print(c.execute('SELECT COUNT(DISTINCT plannerid) FROM runs').fetchone()[0], c.execute('SELECT COUNT(*) FROM runs').fetchone()[0])"
    "${db}" OUTPUT_VARIABLE out RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cannot read ${db}")
  endif()
  string(STRIP "${out}" out)
  if(NOT out MATCHES "^${expected} ${expected}$")
    message(FATAL_ERROR "${db}: expected ${expected} planners with one run each, got '${out}' (planners runs)")
  endif()
endfunction()

# the whole smoke problem, short runs
run_gridcar(0 bench "${SMOKE}" --out "${WORK}/full" --time-limit 0.3)
expect_in("${ERR}" "run 1/1")
foreach(f smoke-q1.log smoke.db report.md smoke-q1-paths.png smoke-q1-box.png)
  if(NOT EXISTS "${WORK}/full/${f}")
    message(FATAL_ERROR "bench did not write ${f}")
  endif()
endforeach()
count_planners("${WORK}/full/smoke.db" 18)
# what Planner Arena reads from the smoke database (tests/planner_arena_schema.py): tables and
# columns, an OMPL version, no path attributes on runs without an exact solution, no empty
# progress columns, one experiment per query, a set-up text naming only planners that ran
execute_process(COMMAND /usr/bin/python3 "${SOURCE_DIR}/tests/planner_arena_schema.py" "${WORK}/full/smoke.db" 1
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the smoke database is not what Planner Arena should read: ${out}${err}")
endif()
# docs/benchmark.md's plotting command leaves the database intact and writes smoke.pdf beside it
execute_process(COMMAND ompl_benchmark_statistics -d smoke.db -p WORKING_DIRECTORY "${WORK}/full"
  RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/full/smoke.pdf")
  message(FATAL_ERROR "ompl_benchmark_statistics -d smoke.db -p wrote no smoke.pdf: ${err}")
endif()
count_planners("${WORK}/full/smoke.db" 18)
file(READ "${WORK}/full/report.md" report)
foreach(p dijkstra corner-astar-physics improved-astar-integral bitstar rrtstar+smooth)
  expect_in("${report}" "| ${p} |")
endforeach()

# two shards write logs only; ompl_benchmark_statistics merges them into one database
run_gridcar(0 bench "${SMOKE}" --out "${WORK}/shards" --time-limit 0.2 --shard 1/2)
run_gridcar(0 bench "${SMOKE}" --out "${WORK}/shards" --time-limit 0.2 --shard 2/2)
file(GLOB logs "${WORK}/shards/*.log")
list(LENGTH logs n)
if(NOT n EQUAL 2)
  message(FATAL_ERROR "expected 2 shard logs, got ${n}: ${logs}")
endif()
execute_process(COMMAND ompl_benchmark_statistics -d "${WORK}/shards/merged.db" ${logs} RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "ompl_benchmark_statistics could not merge the shard logs")
endif()
count_planners("${WORK}/shards/merged.db" 18)
# the report script merges the shards' paths files: the path picture then has every planner
file(GLOB pathfiles "${WORK}/shards/*-paths.json")
execute_process(COMMAND /usr/bin/python3 "${SOURCE_DIR}/scripts/bench_report.py" --db "${WORK}/shards/merged.db"
  --paths ${pathfiles} --out "${WORK}/shards" --title merged RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "bench_report.py could not report the merged shards: ${err}")
endif()
file(READ "${WORK}/shards/report.md" report)
foreach(p dijkstra bitstar rrtstar+smooth)
  expect_in("${report}" "| ${p} |")
endforeach()
if(NOT EXISTS "${WORK}/shards/smoke-q1-paths.png")
  message(FATAL_ERROR "no path picture from the merged shards")
endif()

# bad problem files (exit 2, the file and the reason on stderr), missing and contradictory keys
function(expect_bad_problem name yaml message)
  file(WRITE "${WORK}/${name}.yaml" "${yaml}")
  run_gridcar(2 bench "${WORK}/${name}.yaml" --out "${WORK}/bad")
  expect_in("${ERR}" "${name}.yaml: ${message}")
  set(ERR "${ERR}" PARENT_SCOPE)
endfunction()
set(Q1 "queries: [ {start: [506.749, 380.993], goal: [584.229, 347.319]} ]")
expect_bad_problem(p1 "map: embedded\nqueries:\n  - {start: [506.749, 380.993], goal: [584.229, 347.319]}\nplanners: [dijkstra, rrt-sharp]\n" "unknown planner 'rrt-sharp'")
expect_bad_problem(p2 "map: embedded\nqueries: [ {start: [1, 1], goal: [584.229, 347.319]} ]\nplanners: [dijkstra]\n" "query 1: the start is off the map or in collision")
expect_bad_problem(p3 "map: [unclosed\n" "not valid YAML")
expect_bad_problem(p6 "map: embedded\nplanners: [dijkstra]\n" "'queries' must be a non-empty list")
expect_bad_problem(p7 "map: embedded\n${Q1}\n" "'planners' must be a non-empty list")
expect_bad_problem(p8 "map: embedded\ntime_limit: 2\ntime_limits: [1, 5]\n${Q1}\nplanners: [dijkstra]\n" "give either 'time_limit' or 'time_limits', not both")
expect_bad_problem(p9 "map: embedded\nqueries: [ {start: [506.749, 380.993]} ]\nplanners: [dijkstra]\n" "query 1")
expect_bad_problem(p10 "map: embedded\ntime_limits: [1, -5]\n${Q1}\nplanners: [dijkstra]\n" "every time_limits entry")
file(WRITE "${WORK}/p4.yaml" "map: \${shared}/maps/none/nothing.yaml\nqueries: [ {start: [1, 1], goal: [2, 2]} ]\nplanners: [dijkstra]\n")
run_gridcar(0 bench "${WORK}/p4.yaml" --out "${WORK}/bad" --shared "${WORK}/no-shared-here")
expect_in("${ERR}" "skipped")
# start == goal: a query like any other (an exact solution of no length)
file(WRITE "${WORK}/p11.yaml" "map: embedded\nruns: 1\ntime_limit: 0.5\nqueries: [ {start: [506.749, 380.993], goal: [506.749, 380.993]} ]\nplanners: [corner-astar, dijkstra]\n")
run_gridcar(0 bench "${WORK}/p11.yaml" --out "${WORK}/same" --no-database)

# a directory, given as any YAML file, is bad input (exit 2 naming it), not an internal error
file(MAKE_DIRECTORY "${WORK}/a-dir.yaml")
run_gridcar(2 bench "${WORK}/a-dir.yaml" --out "${WORK}/bad")
expect_in("${ERR}" "a-dir.yaml: is a directory, not a problem file")
run_gridcar(2 info --map "${WORK}/a-dir.yaml")
expect_in("${ERR}" "is a directory, not a map file")
run_gridcar(2 vehicle --vehicle "${WORK}/a-dir.yaml")
expect_in("${ERR}" "is a directory, not a vehicle file")
run_gridcar(2 vehicle --vehicle "${WORK}/no-such-car.yaml")
expect_in("${ERR}" "cannot open the vehicle file")
run_gridcar(2 bench "${SMOKE}" --out "${WORK}/bad" --shard 3/2)
expect_in("${ERR}" "--shard must be K/N")

# ${shared} is the --shared folder relative to the working directory, not to the problem file
file(MAKE_DIRECTORY "${WORK}/sh/maps")
file(WRITE "${WORK}/sh/maps/tiny.map" "type octile\nheight 4\nwidth 6\nmap\n......\n......\n......\n......\n")
file(WRITE "${WORK}/probs/p5.yaml" "map: \${shared}/maps/tiny.map\nvehicle: point\nruns: 1\ntime_limit: 0.2\nqueries: [ {start_cell: [0, 0], goal_cell: [5, 3]} ]\nplanners: [dijkstra]\n")
file(RELATIVE_PATH rel "${CMAKE_CURRENT_BINARY_DIR}" "${WORK}/sh")
run_gridcar(0 bench "${WORK}/probs/p5.yaml" --out "${WORK}/p5" --shared "${rel}" --no-database)
expect_in("${ERR}" "1 logs written")

# Planner Arena: a Reeds-Shepp race at two time limits writes a database in OMPL's schema
# (experiments, plannerConfigs, runs, progress), every exact path drivable, the query one
# experiment name at two time_limit values, RRT*'s progress sampled
file(WRITE "${WORK}/arena.yaml" "name: arena\nmap: embedded\nvehicle: paper-i\nspace: reeds-shepp\ntime_limits: [0.6, 1.2]\nruns: 1\nqueries:\n  - {start: [504.365, 384.271], goal: [587.805, 345.829]}\nplanners:\n  - corner-astar\n  - rrtstar\n  - rrtconnect+simplify\n")
run_gridcar(0 bench "${WORK}/arena.yaml" --out "${WORK}/arena")
expect_in("${ERR}" "query 1 at 1.2 s")
execute_process(COMMAND /usr/bin/python3 "${SOURCE_DIR}/tests/planner_arena_schema.py" "${WORK}/arena/arena.db" 2 2
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the database does not load in Planner Arena's schema: ${out}${err}")
endif()
message(STATUS "${out}")
file(READ "${WORK}/arena/report.md" report)
expect_in("${report}" "## Summary: best driving time per planner and query")
expect_in("${report}" "| corner-astar |")
run_gridcar(0 bench "${WORK}/arena.yaml" --out "${WORK}/arena2" --time-limit 0.2 --report-note "the car's note, \"quoted\"")
file(READ "${WORK}/arena2/report.md" report)
expect_in("${report}" "the car's note, \"quoted\"")
file(WRITE "${WORK}/bad-space.yaml" "name: bad\nmap: embedded\nspace: hovercraft\nqueries:\n  - {start: [1, 1], goal: [2, 2]}\nplanners: [rrt]\n")
run_gridcar(2 bench "${WORK}/bad-space.yaml" --out "${WORK}/bad")
expect_in("${ERR}" "hovercraft")
# found by fuzz_problem_yaml: a map name the file system refuses (over 255 bytes) was an
# internal error (std::filesystem threw); now exit 2 naming the file and the reason
string(REPEAT "x" 300 longname)
expect_bad_problem(p12 "map: ${longname}.yaml\n${Q1}\nplanners: [dijkstra]\n" "map file")
expect_in("${ERR}" "cannot be looked up (File name too long)")
# found by fuzz_problem_yaml: a query that is not a map was an internal error (yaml-cpp threw)
expect_bad_problem(p13 "map: embedded\nqueries: [oops]\nplanners: [dijkstra]\n" "query 1: must be a map")
# found by fuzz_problem_yaml: a cell index beyond int's range reached a cast (undefined behaviour)
expect_bad_problem(p14 "map: embedded\nqueries: [ {start_cell: [3, 45555555555555], goal_cell: [0, 70]} ]\nplanners: [dijkstra]\n" "query 1: start_cell")
