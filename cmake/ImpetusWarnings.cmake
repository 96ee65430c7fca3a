# Warnings and floating-point settings for Impetus' own targets (never for third-party code).
function(impetus_target_settings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
    # No fused multiply-add contraction: results must not depend on the compiler's choice of
    # instructions (determinism across builds).
    -ffp-contract=off)
  if(IMPETUS_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
