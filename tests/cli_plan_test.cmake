# CLI checks of `gridcar plan` and `gridcar scen` on a tiny Moving AI map written here.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
# 12 x 6: a wall at column 6 with a gap in row 4; a closed box at the right (cell 10,1 inside)
file(WRITE "${WORK}/t.map" "type octile\nheight 6\nwidth 12\nmap\n......@..@@@\n......@..@.@\n......@..@@@\n......@.....\n............\n......@.....\n")
file(WRITE "${WORK}/t.map.scen" "version 1\n0\tt.map\t12\t6\t0\t0\t11\t5\t13.07106781\n")

include("${CMAKE_CURRENT_LIST_DIR}/cli_common.cmake")

set(M --map "${WORK}/t.map" --vehicle point)
run_gridcar(0 plan ${M} --planner astar-octile --start-cell 0,0 --goal-cell 11,5 --json --out "${WORK}/p.csv" --png "${WORK}/p.png")
foreach(key "\"status\":\"Exact solution\"" "\"planner\":\"astar-octile\"" "\"cost\":" "\"length\":" "\"expanded\":"
            "\"turns\":" "\"max_turn_deg\":" "\"min_clearance\":" "\"time\":" "\"path\":[[")
  expect_in("${OUT}" "${key}")
endforeach()
expect_in("${OUT}" "\"cost\":13.07106781")  # 4 diagonals + 5 straight, by hand
if(NOT EXISTS "${WORK}/p.png" OR NOT EXISTS "${WORK}/p.csv")
  message(FATAL_ERROR "plan did not write --png / --out")
endif()
run_gridcar(0 plan ${M} --planner corner-astar --start 0.5,5.5 --goal 11.5,0.5 --param corner_weight_45=1.5)
expect_in("${OUT}" "corner-astar: Exact solution")

# bad input: exit 2, one line naming the problem
run_gridcar(2 plan ${M} --planner rrt-sharp --start-cell 0,0 --goal-cell 11,5)
expect_in("${ERR}" "unknown planner 'rrt-sharp'")
run_gridcar(2 plan ${M} --planner corner-astar --start-cell 0,0 --goal-cell 11,5 --param wheels=4)
expect_in("${ERR}" "no parameter 'wheels'")
expect_in("${ERR}" "corner_weight_90")
run_gridcar(2 plan ${M} --planner corner-astar --start-cell 0,0 --goal-cell 11,5 --param corner_weight_90=-3)
run_gridcar(2 plan ${M} --planner astar-octile --start-cell 6,0 --goal-cell 11,5)
expect_in("${ERR}" "in collision")
run_gridcar(2 plan ${M} --planner astar-octile --start 1e9,1 --goal-cell 11,5)
expect_in("${ERR}" "outside the map")
run_gridcar(2 plan ${M} --planner astar-octile --start nan,1 --goal-cell 11,5)
expect_in("${ERR}" "finite")
run_gridcar(2 plan ${M} --planner astar-octile --start-cell 40,1 --goal-cell 11,5)
expect_in("${ERR}" "outside the 12 x 6 map")
run_gridcar(2 plan ${M} --planner astar-octile --start-cell 0,0 --goal-cell 11,5 --time-limit -1)
run_gridcar(2 plan ${M} --planner astar-octile --start-cell 0,0)
run_gridcar(2 plan --map "${WORK}/t.map" --planner astar-octile --start-cell 0,0 --goal-cell 11,5 --vehicle tank)
expect_in("${ERR}" "unknown vehicle preset 'tank'")
# unreachable goal (inside the closed box): planned, no exact solution -> exit 3
run_gridcar(3 plan ${M} --planner astar-octile --start-cell 0,0 --goal-cell 10,1 --json)
expect_in("${OUT}" "Approximate solution")

run_gridcar(0 scen --map "${WORK}/t.map" --scen "${WORK}/t.map.scen")
expect_in("${OUT}" "1 / 1 paths match")
