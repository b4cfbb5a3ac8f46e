# Engine adapters (each directory adapters/ENGINE with install.sh and run.sh, README.md says what
# each models): one smoke test each, label `engine`. Each runs the
# adapter on the platformer examples and adapters/engine_smoke_scenes.jsonl and checks one answer
# line per scene with tilesweep's number of frames and its errors; it is skipped, saying so, when
# the engine's runtime (godot3-server, node) is not installed.
if(TARGET tilesweep_cli AND (TILESWEEP_BUILD_TESTS OR TILESWEEP_BUILD_PROPERTIES))
    file(GLOB engine_installs RELATIVE ${CMAKE_CURRENT_SOURCE_DIR} CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*/install.sh)
    foreach(install ${engine_installs})
        get_filename_component(engine ${install} DIRECTORY)
        add_test(NAME adapters_${engine}_smoke
            COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/engine_smoke_test.sh ${engine} $<TARGET_FILE:tilesweep_cli>
                    ${PROJECT_SOURCE_DIR}/examples/platformer.jsonl ${CMAKE_CURRENT_SOURCE_DIR}/engine_smoke_scenes.jsonl)
        set_tests_properties(adapters_${engine}_smoke PROPERTIES LABELS engine SKIP_RETURN_CODE 77 TIMEOUT 600)
    endforeach()
endif()
