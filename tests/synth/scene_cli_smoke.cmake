# Runs `cloudshape-synth scene` into a fresh folder and checks the labelled cloud, its truth and
# the label-groups sidecar; then that a bad layout is a one-line error with exit status 2.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
execute_process(
  COMMAND "${SYNTH}" scene --layout touching --count 3 --seed 2 --width 160 --height 120
          --depth-noise 0.003 --quantize --shadows --flying-pixels 0.5
          -o "${WORK_DIR}/touching.pcd"
  RESULT_VARIABLE status ERROR_VARIABLE error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cloudshape-synth scene exited with ${status}: ${error}")
endif()
foreach(file touching.pcd touching.json touching.truth.json)
  if(NOT EXISTS "${WORK_DIR}/${file}")
    message(FATAL_ERROR "missing ${file}")
  endif()
endforeach()
file(READ "${WORK_DIR}/touching.pcd" header LIMIT 200)
if(NOT header MATCHES "FIELDS x y z label\n" OR NOT header MATCHES "WIDTH 160\nHEIGHT 120\n")
  message(FATAL_ERROR "unexpected PCD header: ${header}")
endif()
file(READ "${WORK_DIR}/touching.json" truth)
string(JSON layout GET "${truth}" layout)
string(JSON objects LENGTH "${truth}" objects)
string(JSON first_label GET "${truth}" objects 0 label)
string(JSON pairs LENGTH "${truth}" touching)
if(NOT layout STREQUAL "touching" OR NOT objects EQUAL 3 OR NOT first_label EQUAL 20 OR NOT pairs EQUAL 2)
  message(FATAL_ERROR "unexpected ground truth: ${truth}")
endif()
file(READ "${WORK_DIR}/touching.truth.json" groups)
foreach(label 20 30 40)
  string(JSON shape ERROR_VARIABLE missing GET "${groups}" groups ${label})
  if(missing OR NOT shape MATCHES "^(box|cylinder)$")
    message(FATAL_ERROR "group ${label} missing or wrong in ${groups}")
  endif()
endforeach()

# The lidar layout writes its returns unorganized (HEIGHT 1).
execute_process(
  COMMAND "${SYNTH}" scene --layout lidar --azimuth-step 1 -o "${WORK_DIR}/lidar.pcd"
  RESULT_VARIABLE status ERROR_VARIABLE error)
file(READ "${WORK_DIR}/lidar.pcd" header LIMIT 200)
if(NOT status EQUAL 0 OR NOT header MATCHES "HEIGHT 1\n")
  message(FATAL_ERROR "lidar scene: status ${status}, ${error}, header ${header}")
endif()

execute_process(
  COMMAND "${SYNTH}" scene --layout pyramid -o "${WORK_DIR}/bad.pcd"
  RESULT_VARIABLE status ERROR_VARIABLE error)
if(NOT status EQUAL 2 OR NOT error MATCHES "--layout")
  message(FATAL_ERROR "bad --layout gave status ${status}, stderr: ${error}")
endif()
