# gridcar drive / navigate / paper-i / paper-c on the campus map (generated here): outcomes, JSON fields,
# a moving obstacle, a given path, bad scenario and path files.
include("${CMAKE_CURRENT_LIST_DIR}/cli_common.cmake")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
run_gridcar(0 genmap --out "${WORK}/campus.yaml")
set(Q --map "${WORK}/campus.yaml" --vehicle paper-c-robot --start 506.749,380.993 --goal 584.229,347.319)

run_gridcar(0 drive ${Q} --planner corner-astar --json --png "${WORK}/d.png" --out "${WORK}/traj.csv")
foreach(key "\"outcome\":\"reached\"" "\"driving_time\":" "\"path_length\":" "\"cross_track_mean\":"
            "\"cross_track_max\":" "\"min_clearance\":" "\"plan\":{" "\"planner\":\"corner-astar\"")
  expect_in("${OUT}" "${key}")
endforeach()
expect_in("${ERR}" "[drive] wrote ${WORK}/d.png in")
foreach(f d.png traj.csv)
  if(NOT EXISTS "${WORK}/${f}")
    message(FATAL_ERROR "drive did not write ${f}")
  endif()
endforeach()

# a pedestrian crossing the road the robot takes: avoided, goal reached
file(WRITE "${WORK}/ped.yaml" "obstacles:\n  - {name: pedestrian, shape: disc, radius: 0.3, waypoints: [[545, 355], [545, 372]], speed: 0.3, start_time: 60}\n")
run_gridcar(0 drive ${Q} --planner corner-astar --scenario "${WORK}/ped.yaml" --json)
expect_in("${OUT}" "\"outcome\":\"reached\"")

# a given path
run_gridcar(0 plan ${Q} --planner astar-euclidean --out "${WORK}/p.csv" --allow-undrivable)
run_gridcar(0 drive --map "${WORK}/campus.yaml" --vehicle paper-c-robot --path "${WORK}/p.csv")
expect_in("${OUT}" "reached")
# the same path as JSON with radians, driven with the vehicle from a parameters file
run_gridcar(0 plan ${Q} --planner astar-euclidean --out "${WORK}/p.json" --angle-unit rad --allow-undrivable)
file(WRITE "${WORK}/robot.yaml" "vehicle: paper-c-robot\n")
run_gridcar(0 drive --map "${WORK}/campus.yaml" --params-file "${WORK}/robot.yaml" --path "${WORK}/p.json" --json)
expect_in("${OUT}" "\"outcome\":\"reached\"")
file(READ "${WORK}/traj.csv" text)
expect_in("${text}" "t,x,y,yaw_rad,v,steer_rad\n")

# bad input: exit 2 naming the file
file(WRITE "${WORK}/bad.yaml" "obstacles:\n  - {shape: triangle, waypoints: [[0, 0]]}\n")
run_gridcar(2 drive ${Q} --planner corner-astar --scenario "${WORK}/bad.yaml")
expect_in("${ERR}" "bad.yaml: obstacle 1: shape must be disc or box")
file(WRITE "${WORK}/bad.csv" "x,y\n1,2\nthree,4\n")
run_gridcar(2 drive --map "${WORK}/campus.yaml" --path "${WORK}/bad.csv")
expect_in("${ERR}" "bad.csv: line 3")
run_gridcar(2 drive ${Q} --planner corner-astar --dt 0)
expect_in("${ERR}" "--dt")

# paper-i on the embedded campus only (no shared folder, so the Tsudanuma map named in the
# comma-separated --maps is skipped): tables with all six configurations
run_gridcar(0 paper-i --maps campus,tsudanuma --shared "${WORK}/none" --out "${WORK}/p1" --time-limit 10)
file(READ "${WORK}/p1/paper_i_tables.md" t)
foreach(p "Dijkstra" "A* Manhattan" "A* Euclidean" "improved A* (paper)" "improved A* (integral)" "corner A*")
  expect_in("${t}" "| ${p} | exact |")
endforeach()
if(NOT EXISTS "${WORK}/p1/paper_i_campus_area3.png")
  message(FATAL_ERROR "paper-i did not draw the areas")
endif()

# a scenario whose obstacle drives off the map is refused, naming the file and the obstacle
file(WRITE "${WORK}/away.yaml" "obstacles:\n  - {name: drone, shape: disc, radius: 0.3, waypoints: [[545, 355], [1e6, 372]]}\n")
run_gridcar(2 drive ${Q} --planner corner-astar --scenario "${WORK}/away.yaml")
expect_in("${ERR}" "away.yaml: obstacle 1 (drone): waypoint")
expect_in("${ERR}" "is outside the map")

# gridcar navigate: a pallet across the road the robot planned, seen by the sensor and driven
# round after replanning, with a pedestrian crossing further on; a goal inside the pallet is
# reported blocked with the nearest pose reached (exit 3); bad sensor settings exit 2
file(WRITE "${WORK}/pallet.yaml" "obstacles:\n  - {name: pallet, shape: box, size: [4, 4], waypoints: [[532, 368.5]], speed: 0}\n  - {name: pedestrian, shape: disc, radius: 0.3, waypoints: [[565, 343], [565, 356]], speed: 0.5, start_time: 60, loop: true}\n")
run_gridcar(0 navigate ${Q} --scenario "${WORK}/pallet.yaml" --json --png "${WORK}/nav.png" --out "${WORK}/nav.csv")
foreach(key "\"outcome\":\"reached\"" "\"replan_seconds\":[" "\"sensed_cells\":" "\"min_clearance\":" "\"final_pose\":{")
  expect_in("${OUT}" "${key}")
endforeach()
if(OUT MATCHES "\"replans\":0[,}]" OR OUT MATCHES "\"sensed_cells\":0[,}]")
  message(FATAL_ERROR "navigate did not see the pallet or did not replan round it: ${OUT}")
endif()
foreach(f nav.png nav.csv)
  if(NOT EXISTS "${WORK}/${f}")
    message(FATAL_ERROR "navigate did not write ${f}")
  endif()
endforeach()
run_gridcar(0 navigate ${Q})
expect_in("${OUT}" "reached: reached the goal")
expect_in("${OUT}" "0 replans")
run_gridcar(3 navigate --map "${WORK}/campus.yaml" --vehicle paper-c-robot --start 506.749,380.993 --goal 532,368.5
            --scenario "${WORK}/pallet.yaml" --json --time-limit 2)
expect_in("${OUT}" "\"outcome\":\"goal blocked\"")
expect_in("${OUT}" "\"nearest_reachable\":{")
# the same goal with a tolerance (Nav2's goal checker): arrived beside the pallet
run_gridcar(0 navigate --map "${WORK}/campus.yaml" --vehicle paper-c-robot --start 506.749,380.993 --goal 532,368.5
            --scenario "${WORK}/pallet.yaml" --goal-tolerance 3.5 --json --time-limit 2)
expect_in("${OUT}" "\"outcome\":\"reached\"")
run_gridcar(2 navigate ${Q} --goal-tolerance 0.25,abc)
expect_in("${ERR}" "--goal-tolerance '0.25,abc'")
run_gridcar(2 plan ${Q} --planner corner-astar --goal-tolerance 0.25,200)
expect_in("${ERR}" "YAW in [0, 180] deg")
run_gridcar(2 navigate ${Q} --range 0)
expect_in("${ERR}" "--range must be > 0 m")
run_gridcar(2 navigate ${Q} --scenario "${WORK}/bad.yaml")
expect_in("${ERR}" "bad.yaml: obstacle 1: shape must be disc or box")
