# The command line and the benchmark programs on a real map whose origin is not zero (the
# Tsudanuma campus, origin [-100, -172], 0.05 m cells) with goals given as positions (no
# heading) and as poses: every grid planner and both car-lattice planners answer a short query
# exactly, a planned path is driven to the goal, bench_native and bench_drive run a pair each,
# paper-i and paper-c run on the resampled map. Skipped with a message when ../shared is absent.
include("${CMAKE_CURRENT_LIST_DIR}/cli_common.cmake")
set(MAP "${SHARED}/maps/ros/tsudanuma_campus/tsudanuma_all.yaml")
if(NOT EXISTS "${MAP}")
  message("[skipped] ${MAP} is absent: the real-map command-line test needs ../shared beside the repository")
  return()
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

# a goal 6.2 m away in the open, as a position and as a pose; both vehicles for the grid
# planners (paper C's A* baseline), paper C's robot for the car lattice
set(Q --map "${MAP}" --start 4.38,-100.52,0 --time-limit 20 --json)
foreach(goal "10.48,-99.28" "10.48,-99.28,0")
  foreach(planner dijkstra astar-euclidean astar-octile corner-astar-grid improved-astar-grid corner-astar improved-astar)
    set(vehicles paper-c-robot)
    if(planner MATCHES "^(dijkstra|astar-euclidean)$")
      list(APPEND vehicles paper-i)
    endif()
    # the grid-cell searches' paths are not drivable by a car (plan exits 4 unless told); the
    # car lattice's are, with no flag
    set(allow --allow-undrivable)
    if(planner MATCHES "^(corner-astar|improved-astar)$")
      set(allow "")
    endif()
    foreach(vehicle ${vehicles})
      run_gridcar(0 plan ${Q} --goal ${goal} --planner ${planner} --vehicle ${vehicle} ${allow})
      expect_in("${OUT}" "\"status\":\"Exact solution\"")
      # the path ends at the goal's position (yaw in radians in --json)
      string(REGEX MATCH "\\[10\\.48,-99\\.28,[^]]*\\]\\]" last "${OUT}")
      if(last STREQUAL "")
        message(FATAL_ERROR "plan --goal ${goal} --planner ${planner} --vehicle ${vehicle}: the path does not end at (10.48, -99.28): ${OUT}")
      endif()
    endforeach()
  endforeach()
endforeach()

# paper C's A* baseline driven: planned to a position, driven to it
run_gridcar(0 drive --map "${MAP}" --planner astar-euclidean --vehicle paper-c-robot --start 4.38,-100.52,0
            --goal 10.48,-99.28 --time-limit 20 --json)
expect_in("${OUT}" "\"outcome\":\"reached\"")

# the benchmark programs' position goals (one pair each) and the papers' experiments (pose goals)
execute_process(COMMAND "${BENCH_NATIVE}" --map "${MAP}" --vehicle paper-c-car --pairs 1 --campus-pairs 0
                --bitstar-pairs 0 --time-limit 20 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "bench_native: exit ${rc}\n${out}\n${err}")
endif()
foreach(row "improved-astar mode=paper | 1/1 | 1/1 | 1/1 |" "improved-astar mode=integral | 1/1 | 1/1 | 1/1 |"
            "corner-astar | 1/1 | 1/1 | 1/1 |")
  expect_in("${out}" "| ${row}")
endforeach()
execute_process(COMMAND "${BENCH_DRIVE}" --shared "${SHARED}" --only tsudanuma --pairs 1 --no-moving --time-limit 20
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "bench_drive: exit ${rc}\n${out}\n${err}")
endif()
expect_in("${out}" "Runs that did not reach the goal (0)")
run_gridcar(0 paper-i --maps tsudanuma-0.298 --shared "${SHARED}" --out "${WORK}/pi" --time-limit 10)
file(READ "${WORK}/pi/paper_i_tables.md" t)
foreach(p "Dijkstra" "A* Euclidean" "corner A*")
  expect_in("${t}" "| ${p} | exact |")
endforeach()
run_gridcar(0 paper-c --pairs 1 --shared "${SHARED}" --out "${WORK}/pc" --time-limit 10)
file(READ "${WORK}/pc/paper_c_tables.md" t)
expect_in("${t}" "tsudanuma-0.298")
