"""The design studio (``teleop-ui studio``): the article's selection tool (its Figure 8) as a
page in the browser, answering as you click, and a JSON HTTP API beside it.

A layer over the library, never beside it: every answer comes from the public functions the
command line calls (``solve``, ``assign``, ``check_files``, ``identify_fleet``, the reports and
layouts), in the JSON the command line prints with ``--format json``. Nothing here counts,
solves or identifies.

Modules, one concept each:

=====================  ==========================================================
``selection``          a team selection as a URL's query string, and back
``workspace``          what one studio holds: rule sets, uploads, cached solutions
``service``            every answer as data (the API's JSON, the pages' content)
``live``               the live view's feed: a watcher on a thread, its events kept
``security``           the fence: the token, this account, no other site's work, sizes
``peers``              which account of the machine a connection comes from (Linux)
``connections``        how many connections, how long a request's head may take
``api``                the JSON HTTP API (``/api/...``, ``/openapi.json``)
``pages``              the HTML pages (templates in ``templates/``, scripts and
                       styles in ``static/``, shipped with the package)
``app``                the ASGI application: pages, API, static files, the fence
``server``             binding the socket, printing the address, serving (uvicorn),
                       cleaning up whatever signals come
=====================  ==========================================================

Starlette, uvicorn, python-multipart and Jinja2 come with the ``studio`` extra; they are
imported only when the studio runs.
"""
