# eigen_like_x86_64(SOURCE DEST): a copy of Eigen's headers whose NEON code on aarch64 rounds
# exactly as its SSE2 code on x86_64 (the linux64 build: baseline x86_64, no FMA), so that the
# aarch64 FMU's outputs equal linux64's bit for bit. Eigen 3.4 on AArch64 differs in three
# places, each changed here by an exact text replacement (an error if Eigen's text differs):
# - Packet2d pmadd is a fused vfmaq_f64 where __ARM_FEATURE_FMA is set (always on AArch64):
#   it becomes vmlaq_f64, a multiply and then an add under -ffp-contract=off;
# - EIGEN_HAS_SINGLE_INSTRUCTION_MADD and 32 registers make the matrix-product kernel (GEBP)
#   block rows by 3 packets instead of 2, so rows fall into kernels that sum in another order:
#   not defined, and 16 registers, as SSE2;
# - the NEON GEBP specialization for double (fused lane multiply-adds) is left out with it.
# Everything else, packet size 2 and the reductions, is already the same.
function(eigen_like_x86_64 source dest)
  file(REMOVE_RECURSE ${dest})
  file(COPY ${source}/Eigen DESTINATION ${dest})
  set(neon ${dest}/Eigen/src/Core/arch/NEON)
  function(replace file old new)
    file(READ ${file} text)
    string(FIND "${text}" "${old}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "eigen_like_x86_64: ${file} does not hold the text this build changes "
                          "(another Eigen than 3.4?):\n${old}")
    endif()
    string(REPLACE "${old}" "${new}" text "${text}")
    file(WRITE ${file} "${text}")
  endfunction()
  replace(${neon}/PacketMath.h
          "#ifndef EIGEN_HAS_SINGLE_INSTRUCTION_MADD\n#define EIGEN_HAS_SINGLE_INSTRUCTION_MADD\n#endif\n"
          "")
  replace(${neon}/PacketMath.h
          "#if EIGEN_ARCH_ARM64\n#define EIGEN_ARCH_DEFAULT_NUMBER_OF_REGISTERS 32"
          "#if EIGEN_ARCH_ARM64\n#define EIGEN_ARCH_DEFAULT_NUMBER_OF_REGISTERS 16")
  replace(${neon}/PacketMath.h
          "#ifdef __ARM_FEATURE_FMA\n// See bug 936. See above comment about FMA for float.\ntemplate<> EIGEN_STRONG_INLINE Packet2d pmadd"
          "#if 0  // not fused, as SSE2 (cmake/eigen_like_x86_64.cmake)\ntemplate<> EIGEN_STRONG_INLINE Packet2d pmadd")
  replace(${neon}/GeneralBlockPanelKernel.h "#if EIGEN_ARCH_ARM64\n"
          "#if EIGEN_ARCH_ARM64 && defined(EIGEN_HAS_SINGLE_INSTRUCTION_MADD)\n")
endfunction()
