# Runs `cloudshape-synth shape` into a fresh folder and checks the cloud and its ground truth.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
execute_process(
  COMMAND "${SYNTH}" shape --shape box --dims 30,20,10 --points 2000 --random-pose
          --noise 0.001 --view 0,0,100 -o "${WORK_DIR}/box.pcd"
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cloudshape-synth shape exited with ${status}")
endif()
foreach(file box.pcd box.json)
  if(NOT EXISTS "${WORK_DIR}/${file}")
    message(FATAL_ERROR "missing ${file}")
  endif()
endforeach()
file(READ "${WORK_DIR}/box.json" truth)
string(JSON shape GET "${truth}" objects 0 shape)
string(JSON points GET "${truth}" points)
if(NOT shape STREQUAL "box" OR NOT points EQUAL 2000)
  message(FATAL_ERROR "unexpected ground truth: ${truth}")
endif()

# A bad argument is a one-line error and exit status 2.
execute_process(
  COMMAND "${SYNTH}" shape --shape box --dims 30,20 -o "${WORK_DIR}/bad.pcd"
  RESULT_VARIABLE status ERROR_VARIABLE error)
if(NOT status EQUAL 2 OR NOT error MATCHES "--dims")
  message(FATAL_ERROR "bad --dims gave status ${status}, stderr: ${error}")
endif()
