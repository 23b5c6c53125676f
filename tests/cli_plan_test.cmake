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
# the picture is matplotlib's (axes, legend), announced on stderr with its time
expect_in("${ERR}" "[plan] drawing ${WORK}/p.png")
expect_in("${ERR}" "[plan] wrote ${WORK}/p.png in")
file(READ "${WORK}/p.png" head LIMIT 24 HEX)
if(NOT head MATCHES "^89504e47")
  message(FATAL_ERROR "p.png is not a PNG: ${head}")
endif()
run_gridcar(0 plan ${M} --planner corner-astar --start 0.5,5.5 --goal 11.5,0.5 --param corner_weight_45=1.5)
expect_in("${OUT}" "corner-astar: Exact solution")
# a refused value: exit 2, one message naming the parameter, its value and what it takes, and
# nothing of OMPL's internals
foreach(bad "heuristic_weight=abc;a number in [1, 100]" "cost=tiem;'corners' or 'time'" "reverse=maybe;off (0, false), on (1, true) or auto")
  list(GET bad 0 setting)
  list(GET bad 1 takes)
  run_gridcar(2 plan ${M} --planner corner-astar --start 0.5,5.5 --goal 11.5,0.5 --param ${setting})
  expect_in("${ERR}" "parameter ${setting} not accepted")
  expect_in("${ERR}" "${takes}")
  foreach(leak "GenericParam.h" "Warning:" "Invalid value format")
    string(FIND "${ERR}" "${leak}" pos)
    if(NOT pos EQUAL -1)
      message(FATAL_ERROR "--param ${setting}: OMPL's warning leaked: ${ERR}")
    endif()
  endforeach()
endforeach()
# OMPL's own planners: their parameter named, with its range
run_gridcar(2 plan ${M} --planner rrtconnect --start 0.5,5.5 --goal 11.5,0.5 --param range=abc)
expect_in("${ERR}" "parameter range=abc not accepted")

# a grid-cell search on a car space is told that it ignores the curves
run_gridcar(0 plan --map embedded --planner astar-octile --vehicle paper-c-car --space reeds-shepp --start 504.365,384.271 --goal 587.805,345.829 --allow-undrivable)
expect_in("${ERR}" "warning: astar-octile searches the map's cells in straight steps: on --space reeds-shepp")
# an exact path the independent check finds not drivable (the grid path's corners): exit 4 by
# default, with the reason and the flag that exits 0
run_gridcar(4 plan --map embedded --planner astar-octile --vehicle paper-c-car --start 504.365,384.271 --goal 587.805,345.829)
expect_in("${ERR}" "the path is NOT drivable (curvature")
expect_in("${ERR}" "--allow-undrivable")
run_gridcar(0 plan --map embedded --planner corner-astar --vehicle paper-c-car --start 504.365,384.271 --goal 587.805,345.829)
# --json: one JSON object on stdout whatever happens, a missing map too
run_gridcar(2 plan --map "${WORK}/none.yaml" --planner corner-astar --start 0,0 --goal 1,1 --json)
expect_in("${OUT}" "\"status\":\"Invalid input\"")
expect_in("${OUT}" "none.yaml")
# a goal off the map: the map's extent in the message
run_gridcar(2 plan ${M} --planner astar-octile --start-cell 0,0 --goal 50,50)
expect_in("${ERR}" "outside the map, which spans x 0.000..12.000 m, y 0.000..6.000 m")

# --row-order bottom counts rows from the map origin's row (ROS): cell (0,5) bottom = (0,0) top
run_gridcar(0 plan ${M} --planner astar-octile --start-cell 0,5 --goal-cell 11,0 --row-order bottom --json)
expect_in("${OUT}" "\"cost\":13.07106781")
expect_in("${OUT}" "\"path\":[[0.5,5.5,")
run_gridcar(2 plan ${M} --planner astar-octile --start-cell 0,5 --goal-cell 11,0 --row-order sideways)
expect_in("${ERR}" "--row-order")

# --out in YAML / JSON with the angle unit named; plan --out x.txt refused before planning
run_gridcar(0 plan ${M} --planner astar-octile --start-cell 0,0 --goal-cell 11,5 --out "${WORK}/p.yaml")
file(READ "${WORK}/p.yaml" text)
expect_in("${text}" "angle_unit: deg")
expect_in("${text}" "  - {x: 0.5, y: 5.5, yaw: ")
run_gridcar(0 plan ${M} --planner astar-octile --start-cell 0,0 --goal-cell 11,5 --out "${WORK}/p.json" --angle-unit rad)
file(READ "${WORK}/p.json" text)
expect_in("${text}" "\"angle_unit\": \"rad\"")
file(READ "${WORK}/p.csv" text)
expect_in("${text}" "x,y,yaw_deg\n")
run_gridcar(2 plan ${M} --planner astar-octile --start-cell 0,0 --goal-cell 11,5 --out "${WORK}/p.txt")
expect_in("${ERR}" "must end in .csv, .yaml, .yml or .json")

# --params-file: planner, params, vehicle and time limit from a file; the command line wins
file(WRITE "${WORK}/params.yaml" "planner: Corner-AStar\nparams: {corner_weight_45: 1.5}\nvehicle: point\ntime_limit: 2\n")
run_gridcar(0 plan --map "${WORK}/t.map" --params-file "${WORK}/params.yaml" --start 0.5,5.5 --goal 11.5,0.5)
expect_in("${OUT}" "Corner-AStar: Exact solution")
file(WRITE "${WORK}/params2.yaml" "planner: corner-astar\nparams: {corner_weight_45: -1}\n")
run_gridcar(2 plan ${M} --params-file "${WORK}/params2.yaml" --start 0.5,5.5 --goal 11.5,0.5)
expect_in("${ERR}" "corner_weight_45")
run_gridcar(0 plan ${M} --params-file "${WORK}/params2.yaml" --param corner_weight_45=2 --start 0.5,5.5 --goal 11.5,0.5 --json)
expect_in("${OUT}" "\"planner\":\"corner-astar\"")
file(WRITE "${WORK}/params5.yaml" "planner: corner-astar\n")
run_gridcar(0 plan ${M} --params-file "${WORK}/params5.yaml" --planner astar-octile --start-cell 0,0 --goal-cell 11,5 --json)
expect_in("${OUT}" "\"planner\":\"astar-octile\"")
file(WRITE "${WORK}/params3.yaml" "planer: corner-astar\n")
run_gridcar(2 plan ${M} --params-file "${WORK}/params3.yaml" --start 0.5,5.5 --goal 11.5,0.5)
expect_in("${ERR}" "params3.yaml: unknown key 'planer'")
file(WRITE "${WORK}/params4.yaml" "planner: RRTconect\n")
run_gridcar(2 plan ${M} --params-file "${WORK}/params4.yaml" --start 0.5,5.5 --goal 11.5,0.5)
expect_in("${ERR}" "did you mean 'rrtconnect'")
run_gridcar(2 plan ${M} --start 0.5,5.5 --goal 11.5,0.5)
expect_in("${ERR}" "give --planner NAME (or planner: in --params-file)")
run_gridcar(2 plan ${M} --params-file "${WORK}/none.yaml" --start 0.5,5.5 --goal 11.5,0.5)
expect_in("${ERR}" "none.yaml")

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

# OMPL's RRT* on Reeds-Shepp curves on the embedded campus (paper I's car): the path it returns
# passes the independent dense check (FCL footprint every 2 cm, curvature <= K_max = 0.538 1/m)
execute_process(COMMAND "${GRIDCAR}" plan --map embedded --space reeds-shepp --planner rrtstar
  --start 504.365,384.271 --goal 587.805,345.829 --time-limit 5 --json
  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT (rc EQUAL 0 OR rc EQUAL 3))
  message(FATAL_ERROR "plan --space reeds-shepp --planner rrtstar: exit ${rc}\n${err}")
endif()
string(JSON drivable GET "${out}" drivable)
string(JSON kappa GET "${out}" max_curvature)
string(JSON cusps GET "${out}" cusps)
string(JSON status GET "${out}" status)
message(STATUS "rrtstar on reeds-shepp: ${status}, max curvature ${kappa}, ${cusps} cusp(s), drivable ${drivable}")
if(NOT drivable STREQUAL "ON" AND NOT drivable STREQUAL "true")
  string(JSON why ERROR_VARIABLE none GET "${out}" not_drivable_because)
  message(FATAL_ERROR "rrtstar's Reeds-Shepp path is not drivable: ${why}")
endif()
if(kappa GREATER 0.5385)
  message(FATAL_ERROR "rrtstar's Reeds-Shepp path has curvature ${kappa} > K_max")
endif()
run_gridcar(2 plan --map embedded --space hybrid --planner rrtstar --start 504.365,384.271 --goal 587.805,345.829)
expect_in("${ERR}" "--space")
run_gridcar(2 plan ${M} --space reeds-shepp --planner rrtstar --start-cell 0,0 --goal-cell 11,5)
expect_in("${ERR}" "turning radius")

# a tiny time limit: an answer (exact on this small map, or out of time), never a hang or a crash
foreach(planner corner-astar improved-astar astar-octile rrtconnect)
  execute_process(COMMAND "${GRIDCAR}" plan --map embedded --planner ${planner} --start 504.365,384.271
    --goal 587.805,345.829 --time-limit 0.000001 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT (rc EQUAL 0 OR rc EQUAL 3))
    message(FATAL_ERROR "plan --time-limit 0.000001 --planner ${planner}: exit ${rc}\n${out}${err}")
  endif()
endforeach()
# a grid planner stopped at its memory bound says so (JSON not_exact_because, exit 3)
run_gridcar(3 plan --map embedded --planner corner-astar --param mode=paper --param max_memory_mb=1
  --start 504.365,384.271 --goal 587.805,345.829 --json)
expect_in("${OUT}" "\"not_exact_because\":\"")
expect_in("${OUT}" "max_memory_mb")

# the largest map the readers accept (16384 x 16384, all free): info reports the memory a set-up
# would take and leaves the distance field out, in seconds rather than 21 s and 6 GB
execute_process(COMMAND /usr/bin/python3 -c
  "import sys; f=open(sys.argv[1],'wb'); f.write(b'P5\\n16384 16384\\n255\\n'); row=bytes([254])*16384\nfor i in range(16384): f.write(row)"
  "${WORK}/big.pgm" RESULT_VARIABLE rc)
file(WRITE "${WORK}/big.yaml" "image: big.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
run_gridcar(0 info --map "${WORK}/big.yaml" --json)
expect_in("${OUT}" "\"max_clearance\":null")
expect_in("${OUT}" "\"memory_mb\":{")
file(REMOVE "${WORK}/big.pgm")

# gridcar planners: every planner's parameters with default, range and a line on each
run_gridcar(0 planners --planner corner-astar)
expect_in("${OUT}" "reverse                    default auto")
expect_in("${OUT}" "reverse_zone")
expect_in("${OUT}" "2 R_min + the vehicle's length")
run_gridcar(0 planners --json)
foreach(planner dijkstra corner-astar improved-astar improved-astar-grid rrtstar bitstar)
  expect_in("${OUT}" "\"${planner}\":[")
endforeach()
string(FIND "${ERR}" "Warning" warned)
if(NOT warned EQUAL -1)
  message(FATAL_ERROR "planners printed OMPL's warnings: ${ERR}")
endif()
run_gridcar(2 planners --planner corner-astr)
expect_in("${ERR}" "did you mean 'corner-astar'")
