# spanlight_warnings(target): the warning set every spanlight target builds clean with.
function(spanlight_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wconversion -Wshadow)
endfunction()
