# collide on a fresh Debian 12, with the README's two commands:
#   docker build -t collide .                  # installs the packages, builds, renders the demo
#   docker run --rm collide                    # runs every test (scripts/test.sh)
#   docker run --rm -v "$PWD/out:/src/out" collide build/release/collide render gas -q l
# The course's algs4 files (../shared) are not in the image: the tests that need them are
# reported as skipped.
FROM debian:12
ENV DEBIAN_FRONTEND=noninteractive
WORKDIR /src
COPY . /src
RUN bash scripts/demo.sh && rm -rf /var/lib/apt/lists/*
CMD ["bash", "scripts/test.sh"]
