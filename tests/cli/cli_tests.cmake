# Tests of the `cosserat` command: exit codes and messages for good and bad input.
# Included from tests/CMakeLists.txt, where the target cosserat_cli exists.

set(_cli_dir "${CMAKE_CURRENT_LIST_DIR}")
get_filename_component(_cli_example "${CMAKE_CURRENT_LIST_DIR}/../../examples/cantilever.json"
                       ABSOLUTE)
set(_cli_out "${CMAKE_CURRENT_BINARY_DIR}/cli_out")
file(MAKE_DIRECTORY "${_cli_out}")

# cosserat_cli_test(NAME name ARGS a b c CODE n [STDERR regex] [STDOUT regex] [FILES f ...])
function(cosserat_cli_test)
  cmake_parse_arguments(T "" "NAME;CODE;STDERR;STDOUT;KEEP" "ARGS;FILES" ${ARGN})
  string(REPLACE ";" "|" _args "${T_ARGS}")
  set(_cmd ${CMAKE_COMMAND} "-DEXE=$<TARGET_FILE:cosserat_cli>" "-DARGS=${_args}"
           "-DEXPECT_CODE=${T_CODE}")
  if(DEFINED T_STDERR)
    list(APPEND _cmd "-DEXPECT_STDERR=${T_STDERR}")
  endif()
  if(DEFINED T_STDOUT)
    list(APPEND _cmd "-DEXPECT_STDOUT=${T_STDOUT}")
  endif()
  if(DEFINED T_KEEP)
    list(APPEND _cmd "-DKEEP_FILE=${T_KEEP}")
  endif()
  if(T_FILES)
    string(REPLACE ";" "|" _files "${T_FILES}")
    list(APPEND _cmd "-DEXPECT_FILES=${_files}")
  endif()
  add_test(NAME cli.${T_NAME} COMMAND ${_cmd} -P "${_cli_dir}/expect.cmake")
endfunction()

# Good input.
cosserat_cli_test(NAME version ARGS --version CODE 0 STDOUT "^cosserat [0-9]+\\.[0-9]+")
cosserat_cli_test(NAME help ARGS --help CODE 0 STDOUT "cosserat solve PROBLEM.json")
cosserat_cli_test(NAME validate_example ARGS validate "${_cli_example}" CODE 0
                  STDOUT "cantilever.json: ok")
cosserat_cli_test(NAME solve_example ARGS solve "${_cli_example}" CODE 0
                  STDOUT "\"status\": \"converged\"" STDERR "converged")
cosserat_cli_test(NAME solve_example_files
                  ARGS solve "${_cli_example}" --out "${_cli_out}/result.json"
                       --csv "${_cli_out}/nodes.csv"
                  CODE 0 STDERR "converged"
                  FILES "${_cli_out}/result.json" "${_cli_out}/nodes.csv")

cosserat_cli_test(NAME solve_dynamics
                  ARGS solve "${_cli_dir}/dynamics.json" --csv "${_cli_out}/frames.csv"
                  CODE 0 STDOUT "\"trajectory\": {" STDERR "converged, 100 steps"
                  FILES "${_cli_out}/frames.csv")

# A VTK time series of a dynamics run (read back with VTK in tests/vtk/); a single rod's statics
# is one frame; an assembly's statics is refused.
cosserat_cli_test(NAME solve_dynamics_vtk
                  ARGS solve "${_cli_dir}/dynamics.json" --out "${_cli_out}/vtk_result.json"
                       --vtk "${_cli_out}/vtk"
                  CODE 0 STDERR "frames written to .*dynamics.pvd"
                  FILES "${_cli_out}/vtk/dynamics.pvd" "${_cli_out}/vtk/dynamics_000000.vtp")
cosserat_cli_test(NAME solve_statics_vtk
                  ARGS solve "${_cli_example}" --out "${_cli_out}/vtk_statics.json"
                       --vtk "${_cli_out}/vtk_statics"
                  CODE 0 STDERR "1 frame written to .*cantilever.pvd"
                  FILES "${_cli_out}/vtk_statics/cantilever.pvd"
                        "${_cli_out}/vtk_statics/cantilever_000000.vtp")
cosserat_cli_test(NAME vtk_needs_dynamics
                  ARGS solve "${_cli_dir}/../../examples/l_frame.json" --vtk "${_cli_out}/vtk_frame"
                  CODE 2 STDERR "--vtk writes an assembly's dynamics frames; this assembly's analysis is \"statics\"")
# Refused before the output files are opened: an earlier result in --out survives.
cosserat_cli_test(NAME vtk_statics_keeps_out
                  ARGS solve "${_cli_dir}/../../examples/l_frame.json" --vtk "${_cli_out}/vtk_frame"
                       --out "${_cli_out}/kept.json"
                  CODE 2 KEEP "${_cli_out}/kept.json" STDERR "--vtk writes an assembly's")

# The outputs replace their targets only once the result is written: a run whose --csv cannot
# be written, or that throws during the run, leaves an earlier --out as it was.
cosserat_cli_test(NAME bad_csv_keeps_out
                  ARGS solve "${_cli_example}" --out "${_cli_out}/kept_csv.json"
                       --csv "${_cli_out}/no_such_dir/nodes.csv"
                  CODE 2 KEEP "${_cli_out}/kept_csv.json"
                  STDERR "cannot write .*nodes.csv. \\(no directory .*no_such_dir.\\)")

# A study file's errors name their fields (docs/sweeps.md).
# A problem file given to sweep: one line that says so, not the study keys it lacks.
cosserat_cli_test(NAME sweep_of_a_problem_file ARGS sweep "${_cli_example}" --out "${_cli_out}/p.csv"
                  CODE 2 STDERR "^format: expected \"cosserat-study/1\" \\(a problem file runs with `cosserat solve`.*got \"cosserat-problem/1\"\n?$")
cosserat_cli_test(NAME bad_study ARGS sweep "${_cli_dir}/bad_study.json" --out "${_cli_out}/bad_study.csv"
                  CODE 2 STDERR "parameters\\[0\\].path: names \"/rod/nosuch/x\", but the problem has no \"/rod/nosuch\".*parameters\\[1\\].grid.to: an empty range.*parameters\\[2\\].random.high: expected a bound above \"low\"")

# An output that is an array is written as its JSON text, quoted: every point still counts as
# converged. Two parameters on one place, or an output named like a fixed column, are refused;
# validate checks a study file as one.
cosserat_cli_test(NAME sweep_array_output
                  ARGS sweep "${_cli_dir}/study_array_output.json" --out "${_cli_out}/array.csv"
                  CODE 0 STDERR "sweep complete, 3 points .* 0 not converged")
cosserat_cli_test(NAME study_clashes ARGS validate "${_cli_dir}/study_clashes.json"
                  CODE 2 STDERR "parameters\\[1\\].path: expected a place no other parameter sets \\(parameters\\[0\\] sets it\\).*outputs.status: expected a name other than the fixed columns")
cosserat_cli_test(NAME validate_study ARGS validate "${_cli_dir}/study_array_output.json"
                  CODE 0 STDOUT "ok \\(a study of 3 points\\)")

# --threads takes a whole number from 1 to 4096, written in full: "1e9" is not a count (a prefix
# parse would read 1), and 10⁹ would ask the system for as many threads.
cosserat_cli_test(NAME sweep_threads_not_a_count
                  ARGS sweep "${_cli_dir}/bad_study.json" --out "${_cli_out}/t.csv" --threads 1e9
                  CODE 2 STDERR "--threads needs a whole number from 1 to 4096, got '1e9'")
cosserat_cli_test(NAME sweep_threads_too_many
                  ARGS sweep "${_cli_dir}/bad_study.json" --out "${_cli_out}/t.csv" --threads 1000000000
                  CODE 2 STDERR "--threads needs a whole number from 1 to 4096, got '1000000000'")

# Outputs are checked before the run: a --vtk directory that cannot be made, an option given
# twice, an output over the input file (a copy here, so a failure would not eat the example).
cosserat_cli_test(NAME vtk_directory_unwritable
                  ARGS solve "${_cli_dir}/dynamics.json" --vtk "/proc/cosserat_no_such_dir"
                  CODE 2 STDERR "/proc/cosserat_no_such_dir: cannot create the directory")
cosserat_cli_test(NAME out_given_twice
                  ARGS solve "${_cli_example}" --out "${_cli_out}/a.json" --out "${_cli_out}/b.json"
                  CODE 2 STDERR "--out is given twice")
cosserat_cli_test(NAME out_and_csv_same_file
                  ARGS solve "${_cli_example}" --out "${_cli_out}/same.txt" --csv "${_cli_out}/same.txt"
                  CODE 2 STDERR "--out and --csv name the same file")
file(REMOVE "${_cli_out}/link.json")
file(CREATE_LINK "${_cli_out}/link_target.json" "${_cli_out}/link.json" SYMBOLIC)
cosserat_cli_test(NAME out_and_csv_same_file_through_a_link
                  ARGS solve "${_cli_example}" --out "${_cli_out}/link_target.json" --csv "${_cli_out}/link.json"
                  CODE 2 STDERR "--out and --csv name the same file")
cosserat_cli_test(NAME out_and_csv_same_file_spelt_apart
                  ARGS solve "${_cli_example}" --out "${_cli_out}/same.txt" --csv "${_cli_out}/./same.txt"
                  CODE 2 STDERR "--out and --csv name the same file")
# Inputs no problem could be: a device read without end, nesting thousands of levels deep (each
# level kept its path: memory grew as depth², 3.7 GB at 50 000 levels), a directory.
cosserat_cli_test(NAME validate_endless_input
                  ARGS validate /dev/zero
                  CODE 2 STDERR "/dev/zero: cannot read the file .larger than 256 MiB.")
file(WRITE "${_cli_out}/deep.json" "")
foreach(_i RANGE 200)
  file(APPEND "${_cli_out}/deep.json" "[")
endforeach()
cosserat_cli_test(NAME validate_deep_nesting
                  ARGS validate "${_cli_out}/deep.json"
                  CODE 2 STDERR "invalid JSON: arrays and objects nested deeper than 128 levels")
# A study output whose pointer names nothing in the result fills a blank column: the summary
# says so.
cosserat_cli_test(NAME sweep_output_never_found
                  ARGS sweep "${_cli_dir}/study_output_typo.json" --out "${_cli_out}/typo.csv"
                  CODE 0 STDERR "warning: output \"tip_x\" \\(/tip/positoin/0\\) is empty in every converged point")
cosserat_cli_test(NAME study_of_a_study ARGS validate "${_cli_dir}/study_of_a_study.json"
                  CODE 2 STDERR "problem: expected a problem file, got .*study_of_a_study.json, a study file")
cosserat_cli_test(NAME sweep_out_device
                  ARGS sweep "${_cli_dir}/../../examples/studies/tendon_workspace.json" --out /dev/full
                  CODE 2 STDERR "/dev/full: not a regular file")
cosserat_cli_test(NAME validate_directory
                  ARGS validate "${_cli_out}"
                  CODE 2 STDERR "cannot read the file .it is a directory.")
file(COPY "${_cli_example}" DESTINATION "${_cli_out}/own")
cosserat_cli_test(NAME out_over_the_input
                  ARGS solve "${_cli_out}/own/cantilever.json" --out "${_cli_out}/own/cantilever.json"
                  CODE 2 STDERR "is the input file; choose another name")

# The same release with the order-2 Heun scheme in s (half the stage evaluations).
cosserat_cli_test(NAME solve_dynamics_heun
                  ARGS solve "${_cli_dir}/dynamics_heun.json"
                  CODE 0 STDOUT "\"trajectory\": {" STDERR "converged, 100 steps")

# dt = 0.5 ms on the peer rod: single shooting's exponent λL ≈ 17 is beyond double precision
# (it stops with non_finite after a few steps); 8 pieces run it.
cosserat_cli_test(NAME solve_dynamics_small_dt
                  ARGS solve "${_cli_dir}/dynamics_small_dt.json"
                  CODE 0 STDOUT "\"trajectory\": {" STDERR "converged, 100 steps")

# The same in one piece fails, and the log explains why and what to set.
cosserat_cli_test(NAME solve_dynamics_small_dt_single
                  ARGS solve "${_cli_dir}/dynamics_small_dt_single.json"
                  CODE 1 STDERR "hint: at dt = 0\\.0005 s single shooting amplifies errors by e\\^17\\.3 .*\"shooting_segments\": 4}")

# A free rod at rest in free space stays put: the final tip is exactly where it started.
cosserat_cli_test(NAME solve_free_free
                  ARGS solve "${_cli_dir}/free_free.json"
                  CODE 0 STDERR "converged, 50 steps.*tip at \\[0, 0, 0.5\\] m")

# Bad usage.
cosserat_cli_test(NAME no_command CODE 2 STDERR "usage:")
cosserat_cli_test(NAME unknown_command ARGS frobnicate CODE 2 STDERR "unknown command")
cosserat_cli_test(NAME unknown_option ARGS solve "${_cli_example}" --fast CODE 2
                  STDERR "unknown option '--fast'")
cosserat_cli_test(NAME missing_problem ARGS solve CODE 2 STDERR "needs a problem file")
# An empty output name is refused before the run (else the whole run went first).
cosserat_cli_test(NAME empty_csv_name ARGS solve "${_cli_example}" "--csv="
                  CODE 2 STDERR "--csv needs a file name \\(got an empty one\\)")
cosserat_cli_test(NAME missing_file ARGS validate "${_cli_dir}/does_not_exist.json" CODE 2
                  STDERR "does_not_exist.json: cannot read")

# Bad input files: exit 2, and stderr names the JSON path.
cosserat_cli_test(NAME malformed ARGS validate "${_cli_dir}/malformed.json" CODE 2
                  STDERR "malformed.json: invalid JSON at line 6, column")
cosserat_cli_test(NAME negative_length ARGS solve "${_cli_dir}/negative_length.json" CODE 2
                  STDERR "rod.length: expected a positive number, got -0.5")
cosserat_cli_test(NAME unknown_key ARGS validate "${_cli_dir}/unknown_key.json" CODE 2
                  STDERR "loads.gravty: unknown key \\(did you mean \"gravity\"\\?\\)")
cosserat_cli_test(NAME wrong_type ARGS validate "${_cli_dir}/wrong_type.json" CODE 2
                  STDERR "rod.section.radius: expected a positive number, got a string")
cosserat_cli_test(NAME overflow ARGS validate "${_cli_dir}/overflow.json" CODE 2
                  STDERR "rod.material.youngs_modulus: expected a positive number.*overflow")
cosserat_cli_test(NAME bad_rotation ARGS validate "${_cli_dir}/bad_rotation.json" CODE 2
                  STDERR "base.rotation: expected a rotation matrix")
cosserat_cli_test(NAME many_errors ARGS validate "${_cli_dir}/many_errors.json" CODE 2
                  STDERR "format: .*rod.nodes: .*rod.material: .*loads.tip_force\\[2\\]: ")
cosserat_cli_test(NAME bad_dynamics ARGS solve "${_cli_dir}/bad_dynamics.json" CODE 2
                  STDERR "dynamics.dt: expected a positive number, got -0.002.*dynamics.output_interval: .*dynamics.shooting_segments: .*dynamics.spatial_scheme: .*dynamics.integrator_tolerance: expected a number in \\(0, 0\\.1\\].*dynamics.integrator_max_steps: expected an integer")
cosserat_cli_test(NAME clamped_tip_moment ARGS validate "${_cli_dir}/clamped_tip_moment.json" CODE 2
                  STDERR "loads.tip_moment: a moment at a clamped tip")
# Settings only the other formulation reads are refused, not ignored.
cosserat_cli_test(NAME foreign_formulation_settings
                  ARGS validate "${_cli_dir}/quatfd_foreign_settings.json" CODE 2
                  STDERR "dynamics.shooting_segments: is read by the \"se3-shooting\" formulation only.*dynamics.spatial_scheme: is read by the \"se3-shooting\"")
# A stiff wire struck on quaternion-fd: Radau follows the sections' shear rotation, whose
# frequency sqrt(κGA/ρI)/2π = sqrt(4 κ G/(ρ r²))/2π, κ = 6(1 + ν)/(7 + 6ν) at ν = 0.25, is
# 9.46e5 Hz; the run names it and what damps it.
cosserat_cli_test(NAME quatfd_ringing_note ARGS solve "${_cli_dir}/quatfd_step_moment.json"
                  --out "${_cli_out}/ringing.json" CODE 0
                  STDERR "note: Radau's steps averaged .* = 9.46e.05 Hz, the model's fastest")
cosserat_cli_test(NAME modes_of_a_column ARGS solve "${_cli_dir}/modes_pinned_pinned.json" CODE 0
                  STDERR "converged \\(modes, se3-shooting\\), 4 modes")
cosserat_cli_test(NAME modes_of_a_held_rod_on_quatfd
                  ARGS validate "${_cli_dir}/modes_pinned_pinned_quatfd.json" CODE 2
                  STDERR "modes of a rod held at both ends run as \"boundary\": \"anchored\"")
cosserat_cli_test(NAME assembly_stops_short ARGS solve "${_cli_dir}/l_frame_stops_short.json"
                  CODE 1 STDERR "load_stepping_failed .*the continuation reached 0[.][0-9]+ of the loads")
cosserat_cli_test(NAME truss_pose_jacobian_undefined ARGS solve "${_cli_dir}/truss_pinned.json"
                  CODE 0 STDERR "pose_jacobian is not defined here")
cosserat_cli_test(NAME not_implemented ARGS solve "${_cli_dir}/modes_free_free.json" CODE 2
                  STDERR "boundary: \"free-free\" is not implemented in this version .* for \"analysis\": \"modes\" on \"se3-shooting\"; \"free-free\" runs dynamics on \"se3-shooting\"")

# Natural frequencies. The straight steel wire of modes.json: Euler-Bernoulli gives
# 5.5959 Hz twice (two planes); shear and rotary inertia lower it by ~1e-5. The sagging example:
# both formulations find the pairs split by the sag (5.597/5.598 Hz, 35.06/35.07 Hz); quatfd's
# second-order grid error at 100 segments is ~1e-4 for mode 1 and ~5e-4 for mode 2.
cosserat_cli_test(NAME solve_modes ARGS solve "${_cli_dir}/modes.json" CODE 0
                  STDOUT "\"frequencies_hz\": .[^0-9]*5\\.5958"
                  STDERR "converged \\(modes, se3-shooting\\), 4 modes: 5\\.5958")
cosserat_cli_test(NAME solve_modes_example
                  ARGS solve "${CMAKE_CURRENT_LIST_DIR}/../../examples/modes_cantilever.json"
                       --csv "${_cli_out}/modes_nodes.csv"
                  CODE 0 STDOUT "\"shapes\": .[^0-9]*.displacement"
                  STDERR "4 modes: 5\\.597[0-9]* 5\\.597[0-9]* 35\\.064[0-9]* 35\\.067"
                  FILES "${_cli_out}/modes_nodes.csv")
cosserat_cli_test(NAME solve_modes_quatfd ARGS solve "${_cli_dir}/modes_quatfd.json" CODE 0
                  STDERR "converged \\(modes, quaternion-fd\\), 4 modes: 5\\.59[67][0-9]* 5\\.597[0-9]* 35\\.0[45]")

# The quaternion finite-difference formulation. The static tip x must read -0.1508… or
# -0.1509…: the SE(3) shooting result for the same file at 201 nodes is -0.150858 m, and the
# second-order FD error at 40 segments is ~8e-5 L = 4e-5 m.
cosserat_cli_test(NAME solve_quatfd_statics ARGS solve "${_cli_dir}/quatfd_statics.json"
                  CODE 0 STDOUT "\"status\": \"converged\""
                  STDERR "converged \\(quaternion-fd\\).*tip at .-0\\.150[89]")
cosserat_cli_test(NAME solve_quatfd_dynamics
                  ARGS solve "${_cli_dir}/quatfd_dynamics.json" --csv "${_cli_out}/quatfd_frames.csv"
                  CODE 0 STDOUT "\"trajectory\": {"
                  STDERR "converged \\(quaternion-fd, radau: ok\\)"
                  FILES "${_cli_out}/quatfd_frames.csv")
# The same run at integrator_tolerance 1e-3: fewer steps than the default 1e-6 (232; measured
# 187, asked < 200) and the tip still within 1e-6 m of a run at 1e-8 (-0.00297014 m; measured
# -0.00297021).
cosserat_cli_test(NAME solve_quatfd_dynamics_loose ARGS solve "${_cli_dir}/quatfd_dynamics_loose.json"
                  CODE 0 STDERR "radau: ok\\), 1[0-9][0-9] steps.*tip at .-0\\.002970[0-9]")
# An exploding rod (gravity 1e9 m/s^2): Radau's step collapses to ~1e-9 s; the step cap per
# output interval (2 000 here, 1e6 by default) ends the run with a status, inside the first frame,
# instead of running for hours.
cosserat_cli_test(NAME quatfd_step_cap ARGS solve "${_cli_dir}/quatfd_step_cap.json" CODE 1
                  STDOUT "\"status\": \"max_iterations\"" STDERR "radau: max_steps\\), 1[0-9][0-9][0-9] steps, [0-9]+ rejected.*hint: Radau took dynamics.integrator_max_steps \\(2000\\) steps within one output interval, the last of [0-9.]+e-0[89] s")
cosserat_cli_test(NAME bad_quatfd_frames ARGS validate "${_cli_dir}/bad_quatfd_frames.json" CODE 2
                  STDERR "dynamics.output_interval: expected an interval giving at most 1000000 frames over duration \\(0\\.05 s\\), got 1e-09, 5e\\+07 frames")
cosserat_cli_test(NAME quatfd_free_free ARGS solve "${_cli_dir}/quatfd_free_free.json" CODE 2
                  STDERR "boundary: \"free-free\" is not implemented in this version \\(supported: \"cantilever\", \"anchored\"\\)")

# Stiffness profiles. A jammed-compliant-jammed rod under a pure tip moment: every
# error in a bad profile is reported with its path; the good one solves (the curvature ratio is
# checked against the stiffness ratio in test_stiffness_profiles).
cosserat_cli_test(NAME bad_stiffness_profile
                  ARGS validate "${_cli_dir}/bad_stiffness_profile.json" CODE 2
                  STDERR "rod.stiffness_profile.layer_modlus: unknown key for a \"jamming\" profile \\(did you mean \"layer_modulus\"\\?\\).*rod.stiffness_profile.pressure: expected a number >= 0, got -3000.*rod.stiffness_profile.tube_modulus.table\\[2\\]\\[0\\]: expected a pressure greater than.*rod.stiffness_profile.segments\\[1\\].start: expected a number >= 0.2 .*must not overlap")
cosserat_cli_test(NAME solve_jamming_profile ARGS solve "${_cli_dir}/jamming_profile.json"
                  CODE 0 STDOUT "\"status\": \"converged\"" STDERR "converged")

# Robots: every description file in robots/ solves; bad robot input names the field.
file(GLOB _robot_files "${CMAKE_CURRENT_LIST_DIR}/../../robots/*.json")
foreach(_robot IN LISTS _robot_files)
  get_filename_component(_robot_name "${_robot}" NAME_WE)
  cosserat_cli_test(NAME robot_${_robot_name} ARGS solve "${_robot}" CODE 0
                    STDOUT "\"(robot|assembly)\": {" STDERR "converged")
endforeach()
cosserat_cli_test(NAME bad_robot ARGS validate "${_cli_dir}/bad_robot.json" CODE 2
                  STDERR "robot.colour: unknown key.*robot.tendons\\[0\\].offset: expected an offset within the section.*robot.tendons\\[1\\].pich: unknown key.*did you mean \"pitch\".*robot.tendons\\[1\\].pitch: expected .*missing.*robot.actuation.tension\\[1\\]: expected a tension >= 0.*robot.actuation.pressure: expected a number >= 0, got -5")
# Chambers: every bad one is named by its path (outside the section, negative area, from >= to),
# and the pressures must match the chambers.
cosserat_cli_test(NAME bad_chambers ARGS validate "${_cli_dir}/bad_chambers.json" CODE 2
                  STDERR "robot.chambers\\[1\\].offset: expected a chamber within the section.*robot.chambers\\[2\\].area: expected a positive number.*robot.chambers\\[3\\].to: expected from < to.*robot.actuation.chamber_pressure: expected one value per chamber \\(4 in robot.chambers\\)")
# A finite pressure whose stiffness overflows: the actuation is named, not the section.
cosserat_cli_test(NAME jamming_pressure_overflow ARGS validate "${_cli_dir}/jamming_pressure_overflow.json" CODE 2
                  STDERR "^robot.actuation: under it the section's stiffness or mass per length at s = 0 m is not a finite number")
# Two chambers in one place across the section, over the same span: refused at the later one.
cosserat_cli_test(NAME overlapping_chambers ARGS validate "${_cli_dir}/overlapping_chambers.json" CODE 2
                  STDERR "robot.chambers\\[1\\].offset: expected a chamber apart from robot.chambers\\[0\\], which runs beside it")
# The pneumatic finger without its sphere on the quaternion-FD formulation (robots/ files run on
# SE(3) shooting above): the chamber reaches both formulations through the section law, and the
# result reports the robot's pressures as the SE(3) one does.
cosserat_cli_test(NAME pneumatic_finger_quatfd ARGS solve "${_cli_dir}/pneumatic_finger_quatfd.json"
                  CODE 0 STDOUT "\"status\": \"converged\".*\"robot\": {[^}]*\"kind\": \"pneumatic\",[^}]*\"chamber_pressure\"" STDERR "converged")
# An eversion robot grids its body at 40 nodes per metre: a 1e9 m one is refused, not gridded.
cosserat_cli_test(NAME eversion_too_long ARGS solve "${_cli_dir}/eversion_too_long.json" CODE 2
                  STDERR "rod.length: expected at most 25000 m for an eversion robot.*got 1e\\+09")
cosserat_cli_test(NAME tendon_dynamics ARGS solve "${_cli_dir}/tendon_dynamics.json" CODE 0
                  STDOUT "\"trajectory\"" STDERR "converged, 20 steps")

# Buckling: Euler's pinned-pinned column (pi^2 EI / L^2 = 6.2013 N; shear and shortening add
# 3e-5), and a banded cantilever under its weight that buckles at the band [0.3, 0.35] m.
get_filename_component(_cli_buckling "${CMAKE_CURRENT_LIST_DIR}/../../examples/buckling_column.json"
                       ABSOLUTE)
cosserat_cli_test(NAME buckling_preloaded ARGS solve "${_cli_dir}/buckling_preloaded.json" CODE 0
                  STDERR "critical tip_force 4.201.* on top of loads.tip_force")
cosserat_cli_test(NAME solve_buckling_column ARGS solve "${_cli_buckling}" CODE 0
                  STDOUT "\"critical_load\": 6\\.201[0-9]*,[^}]*\"mode_s_max\": 0\\.25,"
                  STDERR "buckling found \\(pinned-pinned\\), critical tip_force 6\\.201")
# The same analysis on the quaternion-FD formulation: Euler's cantilever, pi^2 EI/(4 L^2) =
# 1.5503 N, 1.6e-4 lower at 40 segments (second order, test_quatfd_buckling.cpp).
cosserat_cli_test(NAME solve_buckling_quatfd ARGS solve "${_cli_dir}/buckling_quatfd.json" CODE 0
                  STDOUT "\"critical_load\": 1\\.550[0-9]*,"
                  STDERR "buckling found \\(cantilever, quaternion-fd\\), critical tip_force 1\\.550")
cosserat_cli_test(NAME solve_buckling_banded ARGS solve "${_cli_dir}/buckling_cantilever_banded.json"
                  CODE 0 STDOUT "\"mode_s_max\": 0\\.3[0-4,]"
                  STDERR "buckling found \\(cantilever\\)")

# Buckling along actuation paths (tests/test_buckling_load_paths.cpp has the analysis).
# Tendon tension alone is self-equilibrated and never buckles the rod: two offset tendons pulled
# 2:1 up to 2 400 N (10 cantilever Euler loads) find nothing: "not_found", critical_load null,
# exit 0 (the convention of every not-found search).
cosserat_cli_test(NAME solve_buckling_tendon ARGS solve "${_cli_dir}/buckling_tendon.json" CODE 0
                  STDOUT "\"critical_load\": null,.*\"status\": \"not_found\".*\"tension_per_unit\": \\[.*1\\.0,.*0\\.5.*\\].*\"load_reached\": 2400\\.0"
                  STDERR "buckling not_found \\(cantilever\\), load reached 2400")
# Pressure: a cantilever tube, E_eff(p) = E0 + k p (E0 = 10 MPa, k = 1e4), I = pi/4 (r_o^4 - r_i^4)
# = 4.5607e-10 m^4, L = 1.25 m, carries the dead tip force P = pi^2 E_eff(20 kPa) I / (4 L^2)
# = 0.151241 N. Euler: it stands while pi^2 E_eff(p) I / (4 L^2) > P, so the lowest pressure is
# p_cr = (4 P L^2 / (pi^2 I) - E0) / k = 20 000 Pa. Shear and extension lower the rod's critical
# load by eps = P/(kappa G A) - P/(E A) = 5.5e-4, which asks E_eff higher by that factor: p_cr about
# 20 011.6 Pa (+5.8e-4). Checked: 20 000 <= p_cr < 20 020 (1e-3).
cosserat_cli_test(NAME solve_buckling_pressure ARGS solve "${_cli_dir}/buckling_pressure.json" CODE 0
                  STDOUT "\"critical_load\": 200[01][0-9]\\.[0-9]*,.*\"status\": \"found\",[^}]*\"load\": \"pressure\""
                  STDERR "buckling found \\(cantilever\\), critical pressure 200[01][0-9]\\.")
cosserat_cli_test(NAME bad_buckling_tendon ARGS validate "${_cli_dir}/bad_buckling_tendon.json"
                  CODE 2 STDERR "buckling.load: expected a load this problem has \\(\"tendon_tension\" needs a robot of robot.kind \"tendon\"\\), got \"tendon_tension\" with no robot")
cosserat_cli_test(NAME bad_buckling_weights ARGS validate "${_cli_dir}/bad_buckling_weights.json"
                  CODE 2 STDERR "buckling.tendons\\[1\\]: expected a weight >= 0, got -1")
cosserat_cli_test(NAME bad_buckling_weight_count
                  ARGS validate "${_cli_dir}/bad_buckling_weight_count.json"
                  CODE 2 STDERR "buckling.tendons: expected one weight per tendon \\(2 in robot.tendons\\), got 1 weight[^s]")
cosserat_cli_test(NAME bad_buckling_pressure ARGS validate "${_cli_dir}/bad_buckling_pressure.json"
                  CODE 2 STDERR "buckling.direction: not used by a \"pressure\" load.*buckling.load: expected a load this problem has \\(\"pressure\" needs a pressure-dependent section")

# Statics of a column: a taut wire pinned at both ends sags under its weight (the value against
# the tensioned-beam solution is checked by python.module and test_column_statics).
get_filename_component(_cli_taut "${CMAKE_CURRENT_LIST_DIR}/../../examples/taut_wire.json" ABSOLUTE)
cosserat_cli_test(NAME solve_taut_wire ARGS solve "${_cli_taut}" CODE 0
                  STDOUT "\"status\": \"converged\"" STDERR "converged.*\\(pinned-pinned\\)")
# A robot on a column is refused by name (its runner is the cantilever's).
cosserat_cli_test(NAME column_robot_refused ARGS validate "${_cli_dir}/column_robot.json" CODE 2
                  STDERR "robot: a robot runs with \"boundary\": \"cantilever\" in statics")

# The environment: a cantilever in a current runs; bad fluid keys are named.
get_filename_component(_cli_current "${CMAKE_CURRENT_LIST_DIR}/../../examples/cantilever_in_current.json"
                       ABSOLUTE)
cosserat_cli_test(NAME solve_cantilever_in_current ARGS solve "${_cli_current}" CODE 0
                  STDERR "converged")
cosserat_cli_test(NAME bad_environment ARGS validate "${_cli_dir}/bad_environment.json" CODE 2
                  STDERR "environment.fluid.drag_normal: .*environment.fluid.diameter: .*environment.fluid.profile.heights: ")
cosserat_cli_test(NAME bad_gust ARGS validate "${_cli_dir}/bad_gust.json" CODE 2
                  STDERR "environment.fluid.gust.amplitude: expected .*environment.fluid.gust.period: expected a positive number, got -3")
cosserat_cli_test(NAME bad_contact ARGS validate "${_cli_dir}/bad_contact.json" CODE 2
                  STDERR "environment.contact\\[0\\].normal: .*environment.contact\\[1\\].radius: .*environment.contact\\[2\\].stiffness: .*environment.contact\\[3\\].friction: ")
get_filename_component(_cli_table "${CMAKE_CURRENT_LIST_DIR}/../../examples/rod_on_table.json"
                       ABSOLUTE)
cosserat_cli_test(NAME solve_rod_on_table ARGS solve "${_cli_table}" CODE 0
                  STDOUT "\"contact\": {.*\"total_force\"" STDERR "converged")
# Its node table carries the contact force per node as three more columns.
cosserat_cli_test(NAME solve_rod_on_table_csv
                  ARGS solve "${_cli_table}" --out "${_cli_out}/table.json" --csv "${_cli_out}/table.csv"
                  CODE 0 STDERR "converged" FILES "${_cli_out}/table.csv")
add_test(NAME cli.rod_on_table_csv_has_contact_columns
         COMMAND ${CMAKE_COMMAND} -DFILE=${_cli_out}/table.csv
                 -DPATTERN=^s,x,y,z,k1,k2,k3,contact_fx,contact_fy,contact_fz
                 -P ${CMAKE_CURRENT_LIST_DIR}/file_matches.cmake)
set_tests_properties(cli.rod_on_table_csv_has_contact_columns PROPERTIES
                     DEPENDS cli.solve_rod_on_table_csv)
cosserat_cli_test(NAME contact_starts_inside ARGS validate "${_cli_dir}/contact_starts_inside.json"
                  CODE 2 STDERR "environment.contact\\[0\\]: the rod starts inside this surface: at s = 0\\.25 m its centreline is 0\\.05 m past it")
# A wall placed at the tip: the rest centreline ends on it (4.4e-16 m past by round-off), which
# is not starting inside it.
cosserat_cli_test(NAME contact_wall_at_tip ARGS validate "${_cli_dir}/contact_wall_at_tip.json"
                  CODE 0 STDOUT "contact_wall_at_tip.json: ok")
# A vine grown at a wall its full length reaches into: refused, saying why the growth's start
# clear of the wall does not count.
cosserat_cli_test(NAME vine_grown_at_a_wall ARGS validate "${_cli_dir}/vine_grown_at_a_wall.json"
                  CODE 2 STDERR "at s = 1\\.2 m its centreline is 0\\.3 m past it \\(a growing rod")
# A stiffness no grid resolves: the hint asks for a lower one, not for more nodes than a problem
# may have (its count had overflowed to a negative number).
cosserat_cli_test(NAME floor_stiffer_than_any_grid
                  ARGS solve "${_cli_dir}/floor_stiffer_than_any_grid.json"
                       --out "${_cli_out}/stiff.json"
                  CODE 1
                  STDERR "lower environment.contact.0..stiffness .the grid it needs, 5.49e.75")
# A smoothing wider than the rod lets it sink into the floor before it is held: warned by name.
cosserat_cli_test(NAME contact_smoothing_wider_than_the_rod
                  ARGS solve "${_cli_dir}/contact_smoothing_wider_than_the_rod.json"
                       --out "${_cli_out}/smooth.json"
                  CODE 0
                  STDERR "environment.contact.0..smoothing is 10 m, more than the rod's width")
# A slack line hanging almost vertically fails from its tight catenary loop; the hint gives the
# loop's radius a (2a sinh(l/2a) = sqrt(L² − h²): 0.0785 m by hand) against the spacing.
cosserat_cli_test(NAME steep_slack_line ARGS solve "${_cli_dir}/steep_slack_line.json" CODE 1
                  STDERR "hint: the line hangs almost straight \\(100 m along its weight, 1 m across, 110 m long\\).*H/w = 0.0785 m, below the grid spacing 0.275 m")
# A sweep parameter inside another's value is named, not left to the JSON library's words.
cosserat_cli_test(NAME sweep_nested_paths ARGS validate "${_cli_dir}/sweep_nested_paths.json" CODE 2
                  STDERR "parameters\\[1\\].path: expected a place apart from parameters\\[0\\]'s \"/robot/actuation/tension\"")
# Tendon lengths and gravity written in mm: each named as a slip of units.
cosserat_cli_test(NAME tendon_lengths_in_mm ARGS solve "${_cli_dir}/tendon_lengths_in_mm.json" CODE 0
                  STDERR "warning: loads.gravity is 9.81e\\+03 m/s², 1000 times Earth's 9.81 \\(over 1000 m/s²\\): check its units.*warning: robot.actuation.length\\[0\\] is 244 m on a 0.25 m rod: check its units \\(m\\)")
# A band between the uniform nodes whose stiffness overflows is caught by validate, on the grid
# the solvers use (its nodes include the band's ends), as an overflow and not as a coupling.
cosserat_cli_test(NAME band_overflow_between_nodes ARGS validate "${_cli_dir}/band_overflow_between_nodes.json"
                  CODE 2 STDERR "rod.section: its stiffness or mass per length at s = 0.201 m is not a finite number")
# Tendons within a rectangle's outline, not its half-diagonal: a parallel offset and a helix.
cosserat_cli_test(NAME tendon_outside_rectangle ARGS validate "${_cli_dir}/tendon_outside_rectangle.json"
                  CODE 2 STDERR "robot.tendons\\[0\\].offset: expected an offset within the rectangle \\(\\|x\\| <= 0.01 m, \\|y\\| <= 0.005 m.*got \\[0, 0.009\\].*robot.tendons\\[1\\].radius: expected a helix within the rectangle \\(radius <= 0.005 m")
# A base so far from the origin that a double loses the rod's deflection is refused, named.
cosserat_cli_test(NAME base_far_away ARGS validate "${_cli_dir}/base_far_away.json" CODE 2
                  STDERR "base.position: expected a point within 1e9 rod lengths \\(5e\\+08 m\\) of the origin.*got 1e\\+16 m away")
# An anchored line starts hung between its held points: an anchor below the sea bed is named.
cosserat_cli_test(NAME anchor_inside_bed ARGS validate "${_cli_dir}/anchor_inside_bed.json"
                  CODE 2 STDERR "environment.contact\\[0\\]: the line is held inside this surface: its anchor\\.position is 2 m past it")

# The soft silicone cantilever with default settings, in both formulations (the SE(3) stepper
# choosing its shooting pieces; the quaternion-FD path at 1 ms frames). Both runs must converge
# over the whole 2 s.
get_filename_component(_cli_soft "${CMAKE_CURRENT_LIST_DIR}/../../bench/problems/soft_cantilever.json"
                       ABSOLUTE)
cosserat_cli_test(NAME solve_soft_cantilever_se3 ARGS solve "${_cli_soft}" CODE 0
                  STDERR "converged, 400 steps, 2 s simulated")
cosserat_cli_test(NAME solve_soft_cantilever_quatfd
                  ARGS solve "${_cli_dir}/soft_cantilever_quatfd.json" CODE 0
                  STDERR "converged \\(quaternion-fd, radau: ok\\).* 2 s simulated")
# Ten times softer at dt = 1 ms the 51-node grid is too coarse for the step: the run fails and
# the log names the exponent per segment and the node count that fixes it (a warning: the shear
# wave's exponent is above 1 per segment, which can grow the motion even in converged steps).
cosserat_cli_test(NAME solve_soft_cantilever_coarse_grid
                  ARGS solve "${_cli_dir}/soft_cantilever_coarse_grid.json" CODE 1
                  STDERR "warning: at dt = 0\\.001 s the grid is coarse for the step: its exponent per segment is 1\\.[0-9]+ .*\"nodes\": [0-9]+}")
# A soft finger pressed onto a sphere touches it along an arc (quaternion-FD statics; the SE(3)
# shooting of the same file puts the tip within 1e-5 m).
get_filename_component(_cli_finger "${CMAKE_CURRENT_LIST_DIR}/../../examples/finger_on_sphere.json"
                       ABSOLUTE)
cosserat_cli_test(NAME solve_finger_on_sphere ARGS solve "${_cli_finger}" CODE 0
                  STDOUT "\"intervals\": \\[[^]]*\\[[^]]*0\\.0[67]" STDERR "converged")
# A free rod sliding down an inclined plane with friction μ = 0.3: the contact report of the
# final state carries the normal force ρ A L g cos θ = 0.17641839 N and the friction
# −μ times it = −0.05292552 N along the slide (the normal transient has died out after 0.3 s;
# at 0.3 m/s the regularisation's deficit (v_ε/v)²/2 is 5e-8), to the 7 digits asserted.
cosserat_cli_test(NAME solve_rod_slides_on_incline
                  ARGS solve "${_cli_dir}/rod_slides_on_incline.json" CODE 0
                  STDOUT "\"total_force\": \\[[^0-9-]*-0\\.0529255[0-9]*,[^]]*0\\.1764183[0-9]*" STDERR "converged")
# The same rod by SE(3) shooting: (k/4EI)^(1/4) L = 25 is beyond single shooting, so statics
# shoots in pieces; it lies on the table from s = 1.07 m, as the quaternion-FD solve finds.
cosserat_cli_test(NAME solve_rod_on_table_se3 ARGS solve "${_cli_dir}/rod_on_table_se3.json" CODE 0
                  STDOUT "\"intervals\": .[^0-9]*1\\.07," STDERR "converged.*shooting pieces")

# Rods held at both ends ("boundary": "anchored", quaternion-FD): the hanging wire's tensions
# (the elastic catenary's H = 9450.07 N and top tension 30791.8 N, tests/test_cables.cpp) and the
# stay cable's first frequency (the taut string's 0.708 Hz); bad anchors name their keys.
get_filename_component(_cli_mooring "${CMAKE_CURRENT_LIST_DIR}/../../examples/catenary_in_water.json"
                       ABSOLUTE)
cosserat_cli_test(NAME solve_catenary_in_water ARGS solve "${_cli_mooring}" CODE 0
                  STDERR "converged.*anchor force \\[9450\\.0[0-9]*, -?0, 2930[0-9.]*\\] N \\(tension 3079[0-9.]* N\\)")
get_filename_component(_cli_stay "${CMAKE_CURRENT_LIST_DIR}/../../examples/stay_cable.json"
                       ABSOLUTE)
cosserat_cli_test(NAME solve_stay_cable ARGS solve "${_cli_stay}" CODE 0
                  STDERR "converged \\(modes, quaternion-fd\\), 8 modes: 0\\.70")
get_filename_component(_cli_riser "${CMAKE_CURRENT_LIST_DIR}/../../examples/riser_on_seabed.json"
                       ABSOLUTE)
cosserat_cli_test(NAME solve_riser_on_seabed ARGS solve "${_cli_riser}" CODE 0 STDERR "converged")
# A vessel heaving and surging at the riser's top (tests/test_cables.cpp checks a shaken string
# against its series solution): the 60 s run on 200 nodes converges.
get_filename_component(_cli_vessel "${CMAKE_CURRENT_LIST_DIR}/../../examples/riser_vessel_motion.json"
                       ABSOLUTE)
cosserat_cli_test(NAME solve_riser_vessel_motion ARGS solve "${_cli_vessel}" --out "${_cli_out}/vessel.json"
                  CODE 0 STDERR "converged \\(quaternion-fd, radau: ok\\).*60 s simulated")
cosserat_cli_test(NAME bad_anchor ARGS validate "${_cli_dir}/bad_anchor.json" CODE 2
                  STDERR "anchor.motion.period: expected a positive number, got -2.*anchor.tip: expected one of \"pinned\", \"clamped\", got \"welded\".*anchor.rotation: is read only with \"tip\": \"clamped\".*anchor.position: expected at most 1.5")
# An anchor beyond the line's reach: a third of stretch is the linear law's answer, named, along
# the whole line (a uniform stretch has no place to name).
cosserat_cli_test(NAME anchor_beyond_reach ARGS solve "${_cli_dir}/anchor_beyond_reach.json"
                  CODE 0 STDERR "warning: the rod is stretched or compressed by 33.3 % of its length along the whole rod: .*few materials follow it so far")
# A slack line with no net weight has no one equilibrium: the failure says why.
cosserat_cli_test(NAME slack_neutral_line ARGS solve "${_cli_dir}/slack_neutral_line.json"
                  CODE 1 STDERR "hint: the line is slack \\(120 m between anchors 94.34 m apart\\) and nothing pulls it sideways")
# Quaternion-FD modes on fine grids: banded when stable and undamped, refused with a reason
# where only the dense spectrum would do.
cosserat_cli_test(NAME stay_cable_fine_modes ARGS solve "${_cli_dir}/stay_cable_fine_modes.json"
                  CODE 0 STDERR "converged \\(modes, quaternion-fd\\), 8 modes: 0\\.7094")
cosserat_cli_test(NAME modes_dense_beyond_reach ARGS solve "${_cli_dir}/modes_dense_beyond_reach.json"
                  CODE 1 STDERR "not_run \\(modes, quaternion-fd\\).*no modes on this grid: the stiffness is not positive definite \\(an unstable equilibrium\\).*rod.nodes <= 801")
# Damped modes take the companion problem, twice the coordinates: refused at 401 nodes' worth.
cosserat_cli_test(NAME modes_damped_beyond_reach
                  ARGS solve "${_cli_dir}/modes_damped_beyond_reach.json"
                  CODE 1 STDERR "not_run \\(modes, quaternion-fd\\).*damped, and the damped modes need the whole spectrum.*on 6000 coordinates.*rod.nodes <= 401 takes the dense spectrum, or without rod.material.damping the undamped modes come from the banded factorisation on any grid, or \"formulation\": \"se3-shooting\"")
# A search along a follower torque finds no static critical load; the log names flutter.
cosserat_cli_test(NAME buckling_follower_torque
                  ARGS solve "${_cli_dir}/buckling_follower_torque.json"
                  CODE 0 STDERR "not_found.*note: the loads are not conservative.*flutter")
# A taut wire's SE(3) modes stop where one shot blurs its pairs, the tension counted.
cosserat_cli_test(NAME modes_taut_wire_blur ARGS solve "${_cli_dir}/modes_taut_wire_blur.json"
                  CODE 1 STDERR "too_few_modes.*6 modes.*resolves frequencies up to about 135 Hz")
# A column in dynamics: its tip slides on the axis under the tip force.
cosserat_cli_test(NAME column_dynamics ARGS solve "${_cli_dir}/column_dynamics.json"
                  CODE 0 STDERR "converged, 500 steps, 0.1 s simulated")
# An inverse pose no rod lengths reach: the direct solve's status, and a hint, not a continuation.
cosserat_cli_test(NAME stewart_gough_beyond_reach ARGS solve "${_cli_dir}/stewart_gough_beyond_reach.json"
                  CODE 1 STDERR "max_iterations \\(assembly, inverse\\).*hint: no rod lengths were found that hold platform at this pose")
# A free rod started at rest on a table: the start fails, and the hint says how to start it.
cosserat_cli_test(NAME free_rod_on_a_table ARGS solve "${_cli_dir}/free_rod_on_a_table.json"
                  CODE 1 STDERR "initial equilibrium did not converge.*hint: a free-free rod under gravity has no unique equilibrium at rest on environment.contact.*initial_loads")
# An assembly swinging through its rest position, where the balance is down to the rods' noise.
cosserat_cli_test(NAME l_frame_swing ARGS solve "${_cli_dir}/l_frame_swing.json"
                  CODE 0 STDERR "converged \\(assembly dynamics\\), 600 steps, 4.128 s simulated")
# The SE(3) modes are undamped: a damped rod is told so, and where the damped ones are.
cosserat_cli_test(NAME modes_damped_se3 ARGS solve "${_cli_dir}/modes_damped_se3.json"
                  CODE 0 STDERR "converged \\(modes, se3-shooting\\).*note: the se3-shooting modes are undamped \\(rod.material.damping is left out\\)")
# A dynamics block kept for another analysis is checked, not used; its base drive is noted.
cosserat_cli_test(NAME modes_keep_base_spin ARGS solve "${_cli_dir}/modes_keep_base_spin.json"
                  CODE 0 STDERR "note: dynamics.base_spin turns the base in \"analysis\": \"dynamics\" only; this \"modes\" holds the base still")
# A length typed in mm: the failed solve's log names the rod's slenderness and the units.
cosserat_cli_test(NAME wire_length_in_mm ARGS solve "${_cli_dir}/wire_length_in_mm.json"
                  CODE 1 STDERR "load_stepping_failed.*hint: the rod is 500 m long and 0.002 m across, 2.5e\\+05 times its width: if rod.length or the section's sizes were meant in mm")
# A file without "analysis" is statics; a dynamics block there is named as not used.
cosserat_cli_test(NAME dynamics_block_without_analysis
                  ARGS solve "${_cli_dir}/dynamics_block_without_analysis.json"
                  CODE 0 STDERR "converged.*note: the file gives no \"analysis\", so this is statics \\(the default\\) and its \"dynamics\" block is not used; \"analysis\": \"dynamics\" runs it")
cosserat_cli_test(NAME anchor_misspelt_position ARGS validate "${_cli_dir}/anchor_misspelt_position.json"
                  CODE 2 STDERR "anchor.postion: unknown key.*anchor.position: expected an array of 3 numbers, got nothing \\(required key is missing\\)\n?$")
# Loads an anchor would take whole are refused, not silently lost.
cosserat_cli_test(NAME loads_at_a_held_tip ARGS validate "${_cli_dir}/loads_at_a_held_tip.json"
                  CODE 2 STDERR "dynamics.initial_loads.tip_force: acts at the anchored tip.*loads.tip_force: acts at the anchored tip, which the anchor holds in place.*loads.tip_moment: acts at the tip, which \"anchor.tip\": \"clamped\" holds")
cosserat_cli_test(NAME anchor_without_boundary ARGS validate
                  "${_cli_dir}/anchor_without_boundary.json" CODE 2
                  STDERR "anchor: is read only with \"boundary\": \"anchored\"")
# The SE(3) path holds rods at both ends in statics: a wire's anchors each carry half its weight
# to 3e-5 (RK4 is not symmetric in s; its horizontal tension, 5.162 N, is the quaternion-FD's on
# 201 nodes to 1e-4); a stay cable on a grid too coarse for its bending boundary layers fails and
# says how many nodes it needs; dynamics is refused.
cosserat_cli_test(NAME anchored_se3 ARGS solve "${_cli_dir}/anchored_se3.json" CODE 0
                  STDERR "converged.*anchor force \\[5\\.162[0-9]*, -?0, 4\\.838[4-6][0-9]*\\] N")
cosserat_cli_test(NAME anchored_se3_coarse ARGS solve "${_cli_dir}/stay_cable_se3_coarse.json"
                  CODE 1 STDERR "boundary layers at the anchors.*try rod.nodes >= 455")
cosserat_cli_test(NAME anchored_se3_dynamics ARGS solve "${_cli_dir}/anchored_se3_dynamics.json"
                  CODE 2 STDERR "boundary: \"anchored\" runs dynamics and modes on the \"quaternion-fd\"")
# A beam clamped at both ends ("tip": "clamped") in both formulations: each anchor carries half
# the load, q L/2 = 30.159 N (tests/test_cables.cpp checks its deflection and end moments
# against beam theory).
cosserat_cli_test(NAME clamped_beam ARGS solve "${_cli_dir}/clamped_beam.json" CODE 0
                  STDERR "converged \\(quaternion-fd\\).*anchor force \\[1\\.53[0-9]*, -?0, 30\\.159[0-9]*\\] N")
cosserat_cli_test(NAME clamped_beam_se3 ARGS solve "${_cli_dir}/clamped_beam_se3.json" CODE 0
                  STDERR "converged.*anchor force \\[1\\.53[0-9]*, -?0, 30\\.159[0-9]*\\] N")

# The drill string: stick-slip from the command line (tests/test_drill_string.cpp checks it
# against the torsional pendulum), and bad bit friction named by key.
get_filename_component(_cli_drill "${CMAKE_CURRENT_LIST_DIR}/../../examples/drill_string_stick_slip.json"
                       ABSOLUTE)
cosserat_cli_test(NAME solve_drill_string ARGS solve "${_cli_drill}" --out "${_cli_out}/drill.json"
                  CODE 0 STDERR "converged, 4000 steps")
# The same string turned by a motor with inertia (tests/test_drill_string.cpp checks the
# table-string-BHA frequency): it runs, and a bad table is named by key.
get_filename_component(_cli_motor "${CMAKE_CURRENT_LIST_DIR}/../../examples/drill_string_motor.json"
                       ABSOLUTE)
cosserat_cli_test(NAME solve_drill_string_motor ARGS solve "${_cli_motor}" --out "${_cli_out}/motor.json"
                  CODE 0 STDERR "converged, 4000 steps")
cosserat_cli_test(NAME bad_rotary_table ARGS validate "${_cli_dir}/bad_rotary_table.json" CODE 2
                  STDERR "dynamics.rotary_table.inertia: expected a positive number, got -5.*dynamics.base_spin: is not read with \"rotary_table\"")
cosserat_cli_test(NAME bad_bit_friction ARGS validate "${_cli_dir}/bad_bit_friction.json" CODE 2
                  STDERR "loads.bit_friction.radius: expected a positive number.*loads.bit_friction.static_coefficient: expected a number >= kinetic_coefficient")
cosserat_cli_test(NAME riser_coarse_grid ARGS solve "${_cli_dir}/riser_coarse_grid.json" CODE 1
                  STDERR "hint: the grid spacing 8.75 m is coarse for environment.contact\\[0\\]'s foundation length.*try rod.nodes >= 119")

cosserat_cli_test(NAME tip_mass_quatfd ARGS validate "${_cli_dir}/tip_mass_quatfd.json" CODE 2
                  STDERR "dynamics.tip_mass: a body at the tip runs on the \"se3-shooting\" formulation's dynamics")
# A step too long for the first bending mode converges to a rod BDF2 has stopped: a warning
# with the amplitude kept per step and the frequency lost (the root of (3 − 2iωdt) ζ² − 4ζ + 1
# near e^{iωdt} at ω dt = 2.2).
cosserat_cli_test(NAME dynamics_coarse_dt ARGS solve "${_cli_dir}/dynamics_coarse_dt.json" CODE 0
                  STDERR "warning: dt = 0.05 s resolves the first bending mode \\(about 6.99 Hz.*runs it 40 % slow and keeps 73.1 %")
# An eversion robot that never kinks reports where it first did as null, not a sentinel.
cosserat_cli_test(NAME eversion_no_kink ARGS solve "${_cli_dir}/eversion_no_kink.json" CODE 0
                  STDOUT "\"status\": \"none\".*\"first_kink_s\": null"
                  STDERR "kink \\(the worst met while growing\\): none")
# SE(3) modes of a rod one shot cannot resolve (a thin hanging cable) say which formulation can.
cosserat_cli_test(NAME modes_hanging_cable_se3 ARGS solve "${_cli_dir}/modes_hanging_cable_se3.json"
                  CODE 1 STDERR "statics_failed.*hint: SE\\(3\\) modes shoot the rod in one piece.*= 70.6.*quaternion-fd")
# Answers only a slip of units gives run, and the log says what to check (run/scale_warnings.hpp);
# a soft rod's SE(3) load steps that stop short say what to try. The gel-soft rod of
# modulus_in_mpa hangs 563 m with a 1.65 rad kink between two of its 41 vertices: under_resolved,
# and the units are still named.
cosserat_cli_test(NAME radius_in_mm ARGS solve "${_cli_dir}/radius_in_mm.json" CODE 0
                  STDERR "warning: the rod is 1 m long and 10 m across: not a slender rod")
cosserat_cli_test(NAME modulus_in_mpa ARGS solve "${_cli_dir}/modulus_in_mpa.json" CODE 1
                  STDERR "warning: the rod is stretched or compressed by .* check the units of the material")
# A grid too coarse for the shape (run/grid_resolution.hpp): a warning with the error it implies
# (an arc at 0.75 rad per segment: about 0.25 % of L, measured 0.26 %), and a shot that ran away
# (1e9 Pa in a gel rod's chamber, 90 rad per segment, "converged" with its tip at 1e255 m) is
# non_finite.
cosserat_cli_test(NAME arc_on_a_coarse_grid ARGS solve "${_cli_dir}/arc_on_a_coarse_grid.json"
                  CODE 0 STDERR "warning: the grid resolves the shape coarsely: the bending turns the section by 0.75 rad per segment.*about 0.253 % of the length.*rod.nodes ≥ 25")
cosserat_cli_test(NAME chamber_pressure_runaway
                  ARGS solve "${_cli_dir}/chamber_pressure_runaway.json" CODE 1
                  STDOUT "\"status\": \"non_finite\"" STDERR "its shot ran away.*turns the section by 90 rad on it.*status non_finite.*units; a finer grid does not follow it")
cosserat_cli_test(NAME soft_rod_coarse_se3 ARGS solve "${_cli_dir}/soft_rod_coarse_se3.json" CODE 1
                  STDOUT "\"status\": \"under_resolved\""
                  STDERR "turns the section by 4.49 rad per segment.*rod.nodes ≥ 720")
cosserat_cli_test(NAME tendon_pulled_too_hard ARGS solve "${_cli_dir}/tendon_pulled_too_hard.json"
                  CODE 1 STDERR "hint: the tendon strain law had no solution.*tendon \"helical\" pulls with tension x offset\\^2 / EI = 1.5")

# Assemblies of rods and bodies (docs/assemblies.md; robots/stewart_gough*.json also run in the
# robots/ loop above). The continuum Stewart-Gough robot's inverse kinematics holds the platform
# at the file's pose and prints the six lengths (each between the 0.4 m start and 0.5 m); its
# forward kinematics at those lengths, rounded to 1 nm, returns the platform to (0, 0.02, 0.45) m
# turned 0.1 rad about z within the rounding (the C++ round trip, tests/test_assembly_io.cpp,
# reaches 1e-10 m at full precision).
set(_cli_robots "${CMAKE_CURRENT_LIST_DIR}/../../robots")
# A mechanism (one rod pinned to a plate loaded by a moment about the pin) finds no equilibrium
# for any part of its load: the log says what to look for.
cosserat_cli_test(NAME assembly_mechanism ARGS solve "${_cli_dir}/assembly_mechanism.json" CODE 1
                  STDERR "reached 0 of the loads.*hint: no part of the loads found an equilibrium.*mechanism")
cosserat_cli_test(NAME assembly_stewart_gough_inverse ARGS solve "${_cli_robots}/stewart_gough.json"
                  CODE 0 STDOUT "\"pose_jacobian\": \\[[^]]*[0-9]"
                  STDERR "converged \\(assembly, inverse\\), [0-9]+ iterations.*platform at \\[0, 0\\.02, 0\\.45\\] m, rotation vector \\[0, 0, 0\\.1\\] rad, lengths \\[0\\.4[0-9]+, 0\\.4[0-9]+, 0\\.4[0-9]+, 0\\.4[0-9]+, 0\\.4[0-9]+, 0\\.4[0-9]+\\] m")
cosserat_cli_test(NAME assembly_stewart_gough_forward
                  ARGS solve "${_cli_robots}/stewart_gough_forward.json" --csv "${_cli_out}/stewart_gough.csv"
                  CODE 0 STDOUT "\"kind\": \"forward\""
                  STDERR "converged \\(assembly, forward\\).*platform at \\[(-?[0-9.]+e-(09|1[0-9])|0), 0\\.02, 0\\.45\\] m, rotation vector \\[(-?[0-9.]+e-(09|1[0-9])|0), (-?[0-9.]+e-(09|1[0-9])|0), 0\\.1\\] rad"
                  FILES "${_cli_out}/stewart_gough.csv")
cosserat_cli_test(NAME assembly_validate ARGS validate "${_cli_robots}/stewart_gough.json" CODE 0
                  STDOUT "stewart_gough.json: ok")
# Two wires under a plate pushed sideways by 0.01 N: guided beams, P L^3/(24 EI) = 3.3157e-4 m
# (the plate's residual turn adds 3.3e-4 of it; tests/test_assembly_io.cpp checks 1e-3).
get_filename_component(_cli_guided "${CMAKE_CURRENT_LIST_DIR}/../../examples/guided_beam.json"
                       ABSOLUTE)
cosserat_cli_test(NAME assembly_guided_beam ARGS solve "${_cli_guided}" CODE 0
                  STDERR "converged \\(assembly, forward\\).*plate at \\[0\\.00033[12][0-9]*, 0, 0\\.5\\] m")
# An L-frame (a rod whose base is on a body): its corner sways P b a²/(2EI) = 0.1500 mm by linear
# beam theory; the solve gives 0.15006 mm (the frame's second-order effects, 4e-4).
get_filename_component(_cli_lframe "${CMAKE_CURRENT_LIST_DIR}/../../examples/l_frame.json" ABSOLUTE)
cosserat_cli_test(NAME assembly_l_frame ARGS solve "${_cli_lframe}" CODE 0
                  STDERR "converged \\(assembly, forward\\).*corner at \\[0\\.0001500[0-9]*, ")
# Bad assemblies: every error names its JSON path.
cosserat_cli_test(NAME bad_assembly_joints ARGS validate "${_cli_dir}/bad_assembly_joints.json"
                  CODE 2 STDERR "assembly.bodies\\[2\\].name: expected a name no other body has.*assembly.rods\\[1\\].name: expected a name no other rod has.*\"leg1\", already the name of assembly.rods\\[0\\].*assembly.rods\\[2\\].tip.body: names \"plate\", but the bodies are \"platform\", \"lid\".*assembly.rods\\[3\\].tip.body: a \"free\" tip joins no body.*assembly.rods\\[3\\].base.joint: expected \"clamped\" unless the tip is clamped.*assembly.bodies\\[1\\]: no rod holds \"lid\"")
cosserat_cli_test(NAME bad_assembly_inverse ARGS validate "${_cli_dir}/bad_assembly_inverse.json"
                  CODE 2 STDERR "assembly.lengths: not read with \"inverse\".*assembly.inverse: expected six rods joined to each body.*got 2 on \"plate\".*assembly.inverse.poses\\[0\\].body: names \"plates\", but the bodies are \"plate\"")
cosserat_cli_test(NAME bad_assembly_keys ARGS validate "${_cli_dir}/bad_assembly_keys.json"
                  CODE 2 STDERR "rod: not read with \"assembly\".*boundary: not read with \"assembly\".*loads.tip_force: not read with \"assembly\"")
cosserat_cli_test(NAME assembly_modes ARGS solve "${_cli_dir}/assembly_modes.json" CODE 2
                  STDERR "analysis: \"modes\" of an \"assembly\" is not implemented in this version")
# Dynamics of an assembly: the plate released on two wires (its period is checked in
# tests/test_assembly_io.cpp); here the CLI runs it to the end.
get_filename_component(_cli_platform "${CMAKE_CURRENT_LIST_DIR}/../../examples/platform_release.json" ABSOLUTE)
cosserat_cli_test(NAME assembly_platform_release ARGS solve "${_cli_platform}" CODE 0
                  STDERR "converged \\(assembly dynamics\\), 400 steps, 8 s simulated")
# A current along a sea bed in statics, where no friction holds what lies on it: noted.
cosserat_cli_test(NAME current_along_seabed ARGS solve "${_cli_dir}/current_along_seabed.json"
                  CODE 0 STDERR "note: the current runs along environment.contact\\[0\\], and statics have no friction")
# Contact friction given to statics: they leave it out (it needs a slip velocity) and say so.
cosserat_cli_test(NAME friction_in_statics ARGS solve "${_cli_dir}/friction_in_statics.json"
                  CODE 0 STDERR "contact\\[0\\].friction = 0.5 acts in dynamics only")
# A force no elastic rod carries (sixteen times EA): the log names the units to check.
cosserat_cli_test(NAME force_beyond_any_rod ARGS solve "${_cli_dir}/force_beyond_any_rod.json"
                  CODE 1 STDERR "warning: the loads add up to 1e\\+07 N, over ten times the rod's axial stiffness")
# A buckling direction across the rod (the default [0, 0, -1] on a level rod) finds nothing; the
# log names the direction that presses it.
cosserat_cli_test(NAME buckling_across_the_rod ARGS solve "${_cli_dir}/buckling_across_the_rod.json"
                  CODE 0 STDERR "buckling not_found \\(cantilever\\).*note: buckling.direction \\[0, 0, -1\\] is mostly across the rod.*axis at its base is \\[1, 0, 0\\].*a direction of \\[-1, 0, 0\\] presses it")
# The summary line names the status the checks after the solve leave, not "converged".
cosserat_cli_test(NAME modes_coarse_summary ARGS solve "${_cli_dir}/modes_coarse_summary.json"
                  CODE 1 STDERR "^cosserat: under_resolved \\(modes, quaternion-fd\\), 8 modes")
# A dynamics run whose shot ran away is non_finite, as a statics is.
cosserat_cli_test(NAME tendon_curls_in_dynamics ARGS solve "${_cli_dir}/tendon_curls_in_dynamics.json"
                  CODE 1 STDERR "^cosserat: non_finite, the initial equilibrium did not converge.*its shot ran away.*rod.nodes ≥ 192")
# A Newton solve that stops with iterations to spare says so in its summary line.
cosserat_cli_test(NAME anchored_wire_stalls ARGS solve "${_cli_dir}/anchored_wire_stalls.json"
                  CODE 1 STDERR "^cosserat: max_iterations, [0-9]+ iterations \\(of 50 allowed: no step lowered the residual further\\).*hint: the grid spacing 0.275 m is coarse")
# A drill pipe spun on a bore's wall: what the weight on bit and the wall's friction leave out.
cosserat_cli_test(NAME drill_pipe_in_a_bore ARGS solve "${_cli_dir}/drill_pipe_in_a_bore.json"
                  CODE 0 STDERR "converged, 5 steps.*note: loads.bit_friction.weight_on_bit \\(5e\\+04 N\\) sets the bit's friction torque only.*note: environment.contact\\[0\\].friction acts on the centreline's velocity only")
# Clamps left at the default rotation on an inclined cable: the log names their angle to the line.
cosserat_cli_test(NAME stay_cable_clamped_upright
                  ARGS solve "${_cli_dir}/stay_cable_clamped_upright.json" CODE 1
                  STDERR "note: the clamp at s = 0 holds the rod's tangent \\[0, 0, 1\\] \\(base.rotation's third column\\) 60.4° from the line's direction beyond its bending layer.*note: the clamp at the anchor holds")
# A buckling search by tendon tension that ends at the tendon law's limit says so.
cosserat_cli_test(NAME tendon_tension_buckling_limit
                  ARGS solve "${_cli_dir}/tendon_tension_buckling_limit.json" CODE 1
                  STDERR "buckling path_failed.*hint: the tension path stopped at 38.2 N added, where tendon \"straight_x\" pulls with tension x offset\\^2 / EI = 0.602")
# Four parallel tendons at 90° make two curvatures and a stretch: their lengths leave the tensions
# free along (1, −1, 1, −1), and the log says the returned set is one of a one-way family.
cosserat_cli_test(NAME four_tendons_given_lengths
                  ARGS solve "${_cli_dir}/four_tendons_given_lengths.json"
                       --out "${_cli_out}/four_tendons.json"
                  CODE 0 STDERR "do not fix the tensions.*can change in 1 way")

# Slips a student makes, each named. A column's tip guide takes a sideways tip force whole; a
# buckling search stopped below the Euler load π²EI/L² (968.9 N for a 1 m steel rod of radius
# 5 mm); steel's modulus in GPa; a rest curvature in degrees (90 rad/m is 90/2π = 14.3 turns).
cosserat_cli_test(NAME column_tip_force_across ARGS solve "${_cli_dir}/column_tip_force_across.json"
                  CODE 0 STDERR "tip guide slides only along its axis .* takes the 10 N of loads.tip_force across it whole")
cosserat_cli_test(NAME buckling_max_below_euler
                  ARGS solve "${_cli_dir}/buckling_max_below_euler.json" CODE 0
                  STDERR "buckling.max \\(100 N\\) is below the Euler load of a uniform rod with these ends, 968.9 N")
cosserat_cli_test(NAME youngs_modulus_in_gpa ARGS solve "${_cli_dir}/youngs_modulus_in_gpa.json"
                  CODE 1 STDERR "youngs_modulus is 200 Pa: if it was meant in GPa or MPa, write it in Pa")
cosserat_cli_test(NAME rest_curvature_in_degrees
                  ARGS solve "${_cli_dir}/rest_curvature_in_degrees.json" CODE 1
                  STDERR "turns the unloaded rod through 14.3 full turns along its length: if it was meant in degrees")

# A vine robot's pressure: given in robot.actuation alone (its profile sets none) it inflates the
# tube, 3 kPa, whose tip force is p π r² = 5.890 N; typed in kPa (3 Pa) it is named.
cosserat_cli_test(NAME eversion_pressure_in_actuation
                  ARGS solve "${_cli_dir}/eversion_pressure_in_actuation.json" CODE 0
                  STDOUT "\"tip_force\": 5.890")
cosserat_cli_test(NAME eversion_pressure_in_kpa ARGS solve "${_cli_dir}/eversion_pressure_in_kpa.json"
                  CODE 0 STDERR "pressure is 3 Pa \\(vine robots run at 1e3.*3e4 Pa\\): check its units")
