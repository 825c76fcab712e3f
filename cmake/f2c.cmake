# cmake -DF2C=f2c -DINPUT=file.f -DOUTPUT_DIR=dir -P cmake/f2c.cmake: the C form of one of
# reference LAPACK's Fortran 77 files, by f2c (Debian's package): the same operations in the
# same order, so that every platform's compiler rounds as gfortran does
# (python_tests/test_lapack_c.py checks the bits). f2c reads Fortran 77, which has no
# RECURSIVE (dgetrf2 calls itself; C allows it anyway); -a keeps local variables on the stack
# (reentrant and recursive, as gfortran's -frecursive), -A writes ANSI C prototypes.
get_filename_component(name ${INPUT} NAME)
file(READ ${INPUT} text)
string(REGEX REPLACE "\n( +)RECURSIVE SUBROUTINE" "\n\\1SUBROUTINE" text "${text}")
file(MAKE_DIRECTORY ${OUTPUT_DIR}/f77)
file(WRITE ${OUTPUT_DIR}/f77/${name} "${text}")
execute_process(COMMAND ${F2C} -A -a -d${OUTPUT_DIR} ${OUTPUT_DIR}/f77/${name}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "f2c failed on ${INPUT}:\n${out}${err}")
endif()
