# gridcar bench end to end on benchmarks/problems/smoke.yaml (every planner, embedded campus):
# .log -> ompl_benchmark_statistics database with every planner's runs -> report.md and plots;
# shards merged into one database; bad problem files exit 2 naming the file.
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

# bad problem files
file(WRITE "${WORK}/p1.yaml" "map: embedded\nqueries:\n  - {start: [506.749, 380.993], goal: [584.229, 347.319]}\nplanners: [dijkstra, rrt-sharp]\n")
run_gridcar(2 bench "${WORK}/p1.yaml" --out "${WORK}/bad")
expect_in("${ERR}" "p1.yaml: unknown planner 'rrt-sharp'")
file(WRITE "${WORK}/p2.yaml" "map: embedded\nqueries: [ {start: [1, 1], goal: [584.229, 347.319]} ]\nplanners: [dijkstra]\n")
run_gridcar(2 bench "${WORK}/p2.yaml" --out "${WORK}/bad")
expect_in("${ERR}" "p2.yaml: query 1: the start is off the map or in collision")
file(WRITE "${WORK}/p3.yaml" "map: [unclosed\n")
run_gridcar(2 bench "${WORK}/p3.yaml" --out "${WORK}/bad")
expect_in("${ERR}" "p3.yaml: not valid YAML")
file(WRITE "${WORK}/p4.yaml" "map: \${shared}/maps/none/nothing.yaml\nqueries: [ {start: [1, 1], goal: [2, 2]} ]\nplanners: [dijkstra]\n")
run_gridcar(0 bench "${WORK}/p4.yaml" --out "${WORK}/bad" --shared "${WORK}/no-shared-here")
expect_in("${ERR}" "skipped")
run_gridcar(2 bench "${SMOKE}" --out "${WORK}/bad" --shard 3/2)
expect_in("${ERR}" "--shard must be K/N")

# ${shared} is the --shared folder relative to the working directory, not to the problem file
file(MAKE_DIRECTORY "${WORK}/sh/maps")
file(WRITE "${WORK}/sh/maps/tiny.map" "type octile\nheight 4\nwidth 6\nmap\n......\n......\n......\n......\n")
file(WRITE "${WORK}/probs/p5.yaml" "map: \${shared}/maps/tiny.map\nvehicle: point\nruns: 1\ntime_limit: 0.2\nqueries: [ {start_cell: [0, 0], goal_cell: [5, 3]} ]\nplanners: [dijkstra]\n")
file(RELATIVE_PATH rel "${CMAKE_CURRENT_BINARY_DIR}" "${WORK}/sh")
run_gridcar(0 bench "${WORK}/probs/p5.yaml" --out "${WORK}/p5" --shared "${rel}" --no-database)
expect_in("${ERR}" "1 logs written")
